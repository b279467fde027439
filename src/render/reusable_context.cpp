#include "render/reusable_context.h"

#include <string>

#include "render/context_reset.h"
#include "render/gl_renderer.h"

namespace shaderport::render {
namespace {

// GetProcAddress needs a plain function; a process has one current context.
GlBackend* current_backend = nullptr;
void* CurrentBackendProc(const char* name) { return current_backend->GetProc(name); }

}  // namespace

bool ReusableContext::Start(RenderOutcome& outcome) {
  backend_ = CreateBackend(kind_);
  std::string error;
  if (!backend_->Start(error)) {
    outcome.status = RenderStatus::kContextFailed;
    outcome.message = std::string(BackendName(kind_)) + ": " + error;
    backend_.reset();
    return false;
  }
  current_backend = backend_.get();
  std::string missing;
  gl_ = {};
  if (!LoadGlFunctions(&CurrentBackendProc, gl_, missing)) {
    outcome.status = RenderStatus::kContextFailed;
    outcome.message = std::string(BackendName(kind_)) + ": no entry point " + missing;
    backend_.reset();
    return false;
  }
  return true;
}

RenderOutcome ReusableContext::Render(const RenderRequest& request) {
  RenderOutcome outcome;
  if (backend_ == nullptr && !Start(outcome)) return outcome;
  outcome = DrawRequest(gl_, request);
  if (!ResetContext(gl_)) backend_.reset();
  return outcome;
}

RenderOutcome RenderInThisProcess(const RenderRequest& request, BackendKind backend) {
  ReusableContext context(backend);
  return context.Render(request);
}

}  // namespace shaderport::render
