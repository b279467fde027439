#include "driver/lsp/lsp_server.h"

#include <algorithm>
#include <utility>

namespace shaderport::driver::lsp {
namespace {

using Json = nlohmann::json;

constexpr int kRequestCancelled = -32800;

bool IsCodeActionRequest(const Json& message) {
  return message.is_object() && message.contains("id") &&
         message.value("method", Json()) == "textDocument/codeAction";
}

}  // namespace

LspServer::LspServer(SessionOptions options, Sender send)
    : session_([&] {
        options.checks_by_caller = true;
        return options;
      }()),
      rules_with_sections_(options.rules_with_sections),
      send_(std::move(send)) {
  checker_ = std::thread([this] { CheckLoop(); });
  renderer_ = std::thread([this] { RenderLoop(); });
}

LspServer::~LspServer() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  checker_.join();
  renderer_.join();
}

void LspServer::SendLocked(const std::vector<Json>& messages) {
  for (const Json& message : messages) send_(message);
}

bool LspServer::Exited() {
  const std::lock_guard lock(mutex_);
  return session_.Exited();
}

int LspServer::ExitCode() {
  const std::lock_guard lock(mutex_);
  return session_.ExitCode();
}

void LspServer::Receive(const Json& message) {
  const std::lock_guard lock(mutex_);
  if (message.is_object() && message.value("method", Json()) == "$/cancelRequest") {
    const Json params = message.value("params", Json::object());
    const Json id = params.is_object() ? params.value("id", Json()) : Json();
    const auto queued = std::find_if(code_actions_.begin(), code_actions_.end(),
                                     [&](const Json& request) { return request["id"] == id; });
    if (!id.is_null() && queued != code_actions_.end()) {
      code_actions_.erase(queued);
      send_({{"jsonrpc", "2.0"},
             {"id", id},
             {"error", {{"code", kRequestCancelled}, {"message", "cancelled"}}}});
    }
    return;
  }
  if (IsCodeActionRequest(message)) {
    code_actions_.push_back(message);  // after the checks of every change before it
  } else {
    SendLocked(session_.Handle(message));
  }
  wake_.notify_all();
}

void LspServer::ReceiveUnreadable(std::string_view what) {
  const std::lock_guard lock(mutex_);
  send_(LspSession::ParseErrorResponse(what));
}

void LspServer::CheckLoop() {
  std::unique_lock lock(mutex_);
  while (true) {
    wake_.wait(lock,
               [&] { return stopping_ || session_.HasCheckWaiting() || !code_actions_.empty(); });
    if (stopping_) return;
    if (std::optional<CheckJob> job = session_.TakeCheck()) {
      lock.unlock();
      DocumentCheck checked = job->Run(rules_with_sections_);
      lock.lock();
      SendLocked(session_.Completed(*job, std::move(checked)));
      continue;
    }
    const Json request = std::move(code_actions_.front());
    code_actions_.pop_front();
    LspSession::CodeActionRequest taken = session_.TakeCodeActionRequest(request);
    if (taken.input) {
      lock.unlock();
      Json actions = ComputeCodeActions(*taken.input);
      lock.lock();
      taken.response = {{"jsonrpc", "2.0"}, {"id", request["id"]}, {"result", std::move(actions)}};
    }
    send_(taken.response);
  }
}

void LspServer::RenderLoop() {
  std::unique_lock lock(mutex_);
  while (true) {
    wake_.wait(lock, [&] { return stopping_ || session_.HasRenderWaiting(); });
    if (stopping_) return;
    std::optional<CheckJob> job = session_.TakeRender();
    if (!job) continue;
    lock.unlock();
    DocumentCheck checked = job->Run(rules_with_sections_);
    lock.lock();
    SendLocked(session_.Completed(*job, std::move(checked)));
  }
}

}  // namespace shaderport::driver::lsp
