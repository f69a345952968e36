// Route tables of the API (docs/server.md "Endpoints", under /api/v1) and of the operations
// endpoints.
#pragma once

#include "server/http/auth.hpp" // authenticate()
#include "server/http/router.hpp"
#include "server/http/server_context.hpp"

#include <nlohmann/json.hpp>

namespace slipfront::server {

void add_job_routes(Router& router, ServerContext& ctx);        // job_handlers.cpp
void add_job_keep_routes(Router& router, ServerContext& ctx);   // job_keep_handlers.cpp
void add_archive_routes(Router& router, ServerContext& ctx);    // archive_handlers.cpp
void add_result_routes(Router& router, ServerContext& ctx);     // result_handlers.cpp
void add_station_routes(Router& router, ServerContext& ctx);    // station_handlers.cpp
void add_ops_routes(Router& router, ServerContext& ctx);        // ops_handlers.cpp
void add_study_routes(Router& router, ServerContext& ctx);      // study_handlers.cpp
void add_study_keep_routes(Router& router, ServerContext& ctx); // study_keep_handlers.cpp
void add_preset_routes(Router& router);                         // preset_handlers.cpp
void add_length_fit_routes(Router& router);                     // length_fit_handlers.cpp

// The OpenAPI 3 description of every endpoint (openapi.cpp).
nlohmann::json openapi_document();
// The paths of tags, notes, archive, delete, exports and imports (openapi_keep.cpp).
void add_keep_share_paths(nlohmann::json& doc);

} // namespace slipfront::server
