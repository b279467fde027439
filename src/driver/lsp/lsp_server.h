// The language server around an LspSession: the caller's thread reads messages and
// answers what needs no glslang at once (hover, definition, references, symbols,
// completion); a checker thread checks changed documents and answers code actions;
// a renderer thread renders saved documents (render-on-save). A check whose document
// changed while it ran is not published (the newer text is checked next); a queued
// code action that the client cancels is answered RequestCancelled. The server does
// no I/O: it hands each outgoing message to the caller's sender, one at a time.
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string_view>
#include <thread>

#include "driver/lsp/lsp_session.h"

namespace shaderport::driver::lsp {

class LspServer {
 public:
  using Sender = std::function<void(const nlohmann::json&)>;

  LspServer(SessionOptions options, Sender send);
  ~LspServer();  // lets the threads finish what they are doing, then joins them
  LspServer(const LspServer&) = delete;
  LspServer& operator=(const LspServer&) = delete;

  // One parsed message, on the reading thread.
  void Receive(const nlohmann::json& message);
  // A message that could not be framed or was not JSON: answered with a parse error.
  void ReceiveUnreadable(std::string_view what);

  bool Exited();
  int ExitCode();

 private:
  void CheckLoop();
  void RenderLoop();
  void SendLocked(const std::vector<nlohmann::json>& messages);

  std::mutex mutex_;  // guards everything below and the sender
  std::condition_variable wake_;
  LspSession session_;
  std::vector<std::string> rules_with_sections_;
  Sender send_;
  std::deque<nlohmann::json> code_actions_;  // requests waiting for the checker
  bool stopping_ = false;
  std::thread checker_;
  std::thread renderer_;
};

}  // namespace shaderport::driver::lsp
