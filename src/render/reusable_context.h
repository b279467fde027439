// The render worker's GL context, kept from one render to the next. A new context
// per render cost a warm render most of its time: creating and destroying it, and
// llvmpipe compiling its setup code again for each. Between renders the context is
// reset to a new one's state (context_reset.h); one that cannot be is dropped and the
// next render makes another.
#pragma once

#include <memory>

#include "render/gl_backend.h"
#include "render/gl_functions.h"
#include "render/render_request.h"

namespace shaderport::render {

class ReusableContext {
 public:
  explicit ReusableContext(BackendKind kind) : kind_(kind) {}
  ReusableContext(const ReusableContext&) = delete;
  ReusableContext& operator=(const ReusableContext&) = delete;

  RenderOutcome Render(const RenderRequest& request);

 private:
  bool Start(RenderOutcome& outcome);

  BackendKind kind_;
  std::unique_ptr<GlBackend> backend_;
  GlFunctions gl_;
};

}  // namespace shaderport::render
