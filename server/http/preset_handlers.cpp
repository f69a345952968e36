// GET /api/v1/presets and /api/v1/presets/{name}: the presets a job may start from
// (api/presets.hpp, docs/presets.md). Read only, no token needed, the same for every user.
#include "api/presets.hpp"
#include "server/http/api_prefix.hpp"
#include "server/http/handlers.hpp"
#include "server/http/responses.hpp"

namespace slipfront::server {

namespace {

Response list_presets(RequestContext& rc) {
  nlohmann::json list = nlohmann::json::array();
  for (const api::Preset& preset : api::presets())
    list.push_back(api::preset_json(preset));
  return json_response(rc.request, http::status::ok, {{"presets", std::move(list)}});
}

Response get_preset(RequestContext& rc) {
  const std::string& name = rc.path_params.at("name");
  const api::Preset* preset = api::find_preset(name);
  if (preset == nullptr)
    return problem_response(rc.request, http::status::not_found,
                            "no preset is called \"" + name + "\" (GET " + api_prefix +
                                "/presets lists them)");
  return json_response(rc.request, http::status::ok, api::preset_json(*preset));
}

} // namespace

void add_preset_routes(Router& router) {
  router.add(http::verb::get, api_prefix + "/presets",
             [](RequestContext& rc) { return list_presets(rc); });
  router.add(http::verb::get, api_prefix + "/presets/{name}",
             [](RequestContext& rc) { return get_preset(rc); });
}

} // namespace slipfront::server
