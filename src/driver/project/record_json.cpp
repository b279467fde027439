#include "driver/project/record_json.h"

#include <nlohmann/json.hpp>

namespace shaderport::driver::project {

std::string ToRecordJson(const ShaderToyProject& project) {
  nlohmann::ordered_json record = {{"id", project.id},
                                   {"name", project.name},
                                   {"author", project.author},
                                   {"license", project.license}};
  nlohmann::ordered_json passes = nlohmann::ordered_json::array();
  for (const ProjectPass& pass : project.passes) {
    nlohmann::ordered_json inputs = nlohmann::ordered_json::array();
    for (const ChannelBinding& input : pass.inputs) {
      // Drawn inputs are known by their src, which exports by id may not spell so.
      std::string src = input.src;
      if (input.source == ChannelSource::kBuffer && input.buffer >= 0)
        src = "/media/previz/buffer0" + std::to_string(input.buffer) + ".png";
      if (input.source == ChannelSource::kCubeBuffer) src = "/media/previz/cubemap00.png";
      inputs.push_back({{"channel", input.channel},
                        {"ctype", input.ctype},
                        {"src", src},
                        {"sampler",
                         {{"filter", input.sampler.filter},
                          {"wrap", input.sampler.wrap},
                          {"vflip", input.sampler.vflip ? "true" : "false"}}}});
    }
    std::string name = pass.name;
    if (pass.kind == model::PassKind::kBuffer && pass.output_buffer >= 0)
      name = BufferTabName(pass.output_buffer);  // render finds buffers by tab name
    passes.push_back({{"type", model::PassKindName(pass.kind)},
                      {"name", name},
                      {"code", pass.code},
                      {"inputs", std::move(inputs)}});
  }
  record["passes"] = std::move(passes);
  return record.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

}  // namespace shaderport::driver::project
