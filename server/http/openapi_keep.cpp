// The OpenAPI paths of "Keep, annotate, share" (docs/server.md): PATCH and DELETE of a job,
// archive and restore, exports and imports of run archives, and the Job fields they add.
// openapi_document() (openapi.cpp) merges them into the document.
#include "server/http/handlers.hpp"

namespace slipfront::server {

namespace {
const char* keep_paths = R"json({
  "/api/v1/jobs/{id}": {
    "patch": {"summary": "Change a run's tags and note after submission (its owner; 422 naming the field, nothing changed)", "security": [{"bearer": []}],
      "parameters": [{"$ref": "#/components/parameters/id"}],
      "requestBody": {"required": true, "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Annotations"}}}},
      "responses": {"200": {"$ref": "#/components/responses/Job"}, "400": {"$ref": "#/components/responses/Problem"},
        "401": {"$ref": "#/components/responses/Problem"}, "403": {"$ref": "#/components/responses/Problem"},
        "404": {"$ref": "#/components/responses/Problem"}, "422": {"$ref": "#/components/responses/Problem"}}},
    "delete": {"summary": "Delete a finished run and its result file (kept while a cache hit shares it); its owner", "security": [{"bearer": []}],
      "parameters": [{"$ref": "#/components/parameters/id"}],
      "responses": {"200": {"description": "Deleted", "content": {"application/json": {"schema": {"type": "object", "properties": {
          "id": {"type": "string"}, "deleted": {"type": "boolean"}, "result_deleted": {"type": "boolean", "description": "false while another run (a cache hit) shares the file"}}}}}},
        "401": {"$ref": "#/components/responses/Problem"}, "403": {"$ref": "#/components/responses/Problem"},
        "404": {"$ref": "#/components/responses/Problem"},
        "409": {"description": "Queued or running (cancel it first), or a run of a study (archive it instead)", "content": {"application/problem+json": {"schema": {"$ref": "#/components/schemas/Problem"}}}}}}
  },
  "/api/v1/studies/{id}": {
    "patch": {"summary": "Change a study's tags and note (its owner; 422 naming the field, nothing changed)", "security": [{"bearer": []}],
      "parameters": [{"$ref": "#/components/parameters/id"}],
      "requestBody": {"required": true, "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Annotations"}}}},
      "responses": {"200": {"$ref": "#/components/responses/Study"}, "400": {"$ref": "#/components/responses/Problem"},
        "401": {"$ref": "#/components/responses/Problem"}, "403": {"$ref": "#/components/responses/Problem"},
        "404": {"$ref": "#/components/responses/Problem"}, "422": {"$ref": "#/components/responses/Problem"}}},
    "delete": {"summary": "Delete a study that is over with its runs and their result files (kept while a run elsewhere shares one); its owner", "security": [{"bearer": []}],
      "parameters": [{"$ref": "#/components/parameters/id"}],
      "responses": {"200": {"description": "Deleted", "content": {"application/json": {"schema": {"type": "object", "properties": {
          "id": {"type": "string"}, "deleted": {"type": "boolean"}, "deleted_jobs": {"type": "array", "items": {"type": "string"}, "description": "its runs, gone with it"},
          "results_deleted": {"type": "integer", "description": "result files removed (a file another run shares stays)"}}}}}},
        "400": {"$ref": "#/components/responses/Problem"}, "401": {"$ref": "#/components/responses/Problem"}, "403": {"$ref": "#/components/responses/Problem"},
        "404": {"$ref": "#/components/responses/Problem"},
        "409": {"description": "Running (cancel it first), or cancelled with a run still stopping", "content": {"application/problem+json": {"schema": {"$ref": "#/components/schemas/Problem"}}}}}}
  },
  "/api/v1/studies/{id}/export": {
    "get": {"summary": "A study that is over with its runs as one archive: study.json (the study, its runs' places) beside the members of a run archive; POST /imports stores it (a token on a server with a token file)", "security": [{"bearer": []}],
      "parameters": [{"$ref": "#/components/parameters/id"}],
      "responses": {"200": {"description": "The archive", "content": {"application/x-tar": {}}},
        "400": {"$ref": "#/components/responses/Problem"}, "401": {"$ref": "#/components/responses/Problem"},
        "404": {"$ref": "#/components/responses/Problem"},
        "409": {"description": "The study runs, or a run's result file is missing or damaged", "content": {"application/problem+json": {"schema": {"$ref": "#/components/schemas/Problem"}}}},
        "422": {"description": "More runs than an archive holds, or larger than --max-export-bytes", "content": {"application/problem+json": {"schema": {"$ref": "#/components/schemas/Problem"}}}},
        "503": {"$ref": "#/components/responses/Unavailable"}}}
  },
  "/api/v1/studies/{id}/archive": {
    "post": {"summary": "Hide a study from GET /studies (never deleted; ?archived=include shows it); its owner", "security": [{"bearer": []}],
      "parameters": [{"$ref": "#/components/parameters/id"}],
      "responses": {"200": {"$ref": "#/components/responses/Study"}, "400": {"$ref": "#/components/responses/Problem"}, "401": {"$ref": "#/components/responses/Problem"},
        "403": {"$ref": "#/components/responses/Problem"}, "404": {"$ref": "#/components/responses/Problem"}}}
  },
  "/api/v1/studies/{id}/restore": {
    "post": {"summary": "List an archived study again; its owner", "security": [{"bearer": []}],
      "parameters": [{"$ref": "#/components/parameters/id"}],
      "responses": {"200": {"$ref": "#/components/responses/Study"}, "400": {"$ref": "#/components/responses/Problem"}, "401": {"$ref": "#/components/responses/Problem"},
        "403": {"$ref": "#/components/responses/Problem"}, "404": {"$ref": "#/components/responses/Problem"}}}
  },
  "/api/v1/jobs/{id}/archive": {
    "post": {"summary": "Hide a run from listings and exports (never deleted; ?archived=include shows it); its owner", "security": [{"bearer": []}],
      "parameters": [{"$ref": "#/components/parameters/id"}],
      "responses": {"200": {"$ref": "#/components/responses/Job"}, "401": {"$ref": "#/components/responses/Problem"},
        "403": {"$ref": "#/components/responses/Problem"}, "404": {"$ref": "#/components/responses/Problem"}}}
  },
  "/api/v1/jobs/{id}/restore": {
    "post": {"summary": "List an archived run again; its owner", "security": [{"bearer": []}],
      "parameters": [{"$ref": "#/components/parameters/id"}],
      "responses": {"200": {"$ref": "#/components/responses/Job"}, "401": {"$ref": "#/components/responses/Problem"},
        "403": {"$ref": "#/components/responses/Problem"}, "404": {"$ref": "#/components/responses/Problem"}}}
  },
  "/api/v1/exports": {
    "get": {"summary": "Finished runs as one tar archive: manifest.json (SHA-256 of every member), runs/<id>/job.json, runs/<id>/result.h5 (docs/server.md, Export and import); a token on a server with a token file", "security": [{"bearer": []}],
      "parameters": [{"name": "ids", "in": "query", "schema": {"type": "string"}, "description": "comma-separated job ids (1..1000); or instead the filters of GET /api/v1/jobs (study_id, tag, where, archived, ...)"}],
      "responses": {"200": {"description": "The archive", "content": {"application/x-tar": {}}},
        "400": {"$ref": "#/components/responses/Problem"}, "401": {"$ref": "#/components/responses/Problem"},
        "404": {"$ref": "#/components/responses/Problem"},
        "409": {"description": "A run is not finished, or its result file is missing or damaged", "content": {"application/problem+json": {"schema": {"$ref": "#/components/schemas/Problem"}}}},
        "422": {"description": "More than 1000 runs match, or the archive is larger than --max-export-bytes", "content": {"application/problem+json": {"schema": {"$ref": "#/components/schemas/Problem"}}}}}},
    "post": {"summary": "The same archive for a list of runs in the body: {\"ids\": [...]} of 1 to 1000 job ids (a query string holds about 400); a token on a server with a token file", "security": [{"bearer": []}],
      "requestBody": {"required": true, "content": {"application/json": {"schema": {"type": "object", "additionalProperties": false, "required": ["ids"],
        "properties": {"ids": {"type": "array", "minItems": 1, "maxItems": 1000, "items": {"type": "string"}}}}}}},
      "responses": {"200": {"description": "The archive", "content": {"application/x-tar": {}}},
        "400": {"$ref": "#/components/responses/Problem"}, "401": {"$ref": "#/components/responses/Problem"},
        "404": {"description": "An id names no job (the pointer /ids/N says which)", "content": {"application/problem+json": {"schema": {"$ref": "#/components/schemas/Problem"}}}},
        "409": {"description": "A run is not finished, or its result file is missing or damaged", "content": {"application/problem+json": {"schema": {"$ref": "#/components/schemas/Problem"}}}},
        "422": {"description": "Not {\"ids\": [1 to 1000 strings]}, or the archive is larger than --max-export-bytes", "content": {"application/problem+json": {"schema": {"$ref": "#/components/schemas/Problem"}}}}}}
  },
  "/api/v1/imports": {
    "post": {"summary": "Store the runs of an export archive: every member checked against the manifest before anything is stored; runs keep their ids when free here; a run already here is skipped (listed in skipped), unless again=true", "security": [{"bearer": []}],
      "parameters": [{"name": "again", "in": "query", "schema": {"type": "boolean", "default": false}, "description": "store the runs already here too, under new ids"}],
      "requestBody": {"required": true, "content": {"application/x-tar": {"schema": {"type": "string", "format": "binary"}}}},
      "responses": {"201": {"description": "Imported (a run already here is skipped, not stored again)", "content": {"application/json": {"schema": {"$ref": "#/components/schemas/ImportAnswer"}}}},
        "200": {"description": "Every run of the archive was already here: nothing stored, each listed in skipped", "content": {"application/json": {"schema": {"$ref": "#/components/schemas/ImportAnswer"}}}},
        "401": {"$ref": "#/components/responses/Problem"}, "413": {"$ref": "#/components/responses/Problem"},
        "422": {"description": "Refused, nothing stored: the title names the member (a checksum that does not match, an unsafe name, a link, a truncated archive)", "content": {"application/problem+json": {"schema": {"$ref": "#/components/schemas/Problem"}}}}}}
  }
})json";

const char* keep_job_fields = R"json({
  "note": {"type": "string", "description": "free text its owner keeps with it (PATCH)"},
  "archived_at": {"type": "string", "nullable": true, "description": "when it was archived; null = listed"},
  "imported_from": {"type": "object", "nullable": true, "description": "an imported run: {server: {host, code_version}, id, submitted_by, exported_at}"}
})json";

const char* import_answer_schema = R"json({"type": "object", "properties": {
  "imported": {"type": "array", "items": {"type": "object", "properties": {"id": {"type": "string"}, "original_id": {"type": "string"}, "url": {"type": "string"}}}},
  "count": {"type": "integer", "description": "runs stored"},
  "skipped": {"type": "array", "description": "runs already here, not stored again", "items": {"type": "object", "properties": {
    "original_id": {"type": "string"}, "id": {"type": "string", "description": "the run here that it is"}, "url": {"type": "string"},
    "reason": {"type": "string", "enum": ["same_origin", "same_result"], "description": "same_origin: the same run of the same server (followed through earlier imports) with the same spec; same_result: a succeeded run here with the same spec and result file (SHA-256)"},
    "detail": {"type": "string"}}}},
  "study": {"type": "object", "description": "a study's archive: the study here (its id is the archive's when free), or skipped: a study of its id was here already", "properties": {
    "id": {"type": "string"}, "original_id": {"type": "string"}, "url": {"type": "string"}, "skipped": {"type": "boolean"}}},
  "warnings": {"type": "array", "items": {"type": "string"}, "description": "what was left out: metric names this server does not write (one line per run)"}}})json";

const char* annotations_schema =
    R"json({"type": "object", "additionalProperties": false, "minProperties": 1,
  "description": "tags replaced (tags) or added and removed (tags_add, tags_remove; not with tags), and/or the note",
  "properties": {"tags": {"type": "array", "maxItems": 32, "items": {"type": "string", "minLength": 1, "maxLength": 64}, "description": "replace every tag (no control characters)"},
    "tags_add": {"type": "array", "maxItems": 32, "items": {"type": "string", "minLength": 1, "maxLength": 64}, "description": "tags added to those kept (each once; at most 32 in all)"},
    "tags_remove": {"type": "array", "maxItems": 32, "items": {"type": "string", "minLength": 1, "maxLength": 64}, "description": "tags removed (one not there is no error)"},
    "note": {"type": "string", "maxLength": 4096, "description": "free text; newlines and tabs allowed, other control characters not; \"\" clears it"}}})json";
} // namespace

void add_keep_share_paths(nlohmann::json& doc) {
  doc["components"]["schemas"]["Annotations"] = nlohmann::json::parse(annotations_schema);
  doc["components"]["schemas"]["ImportAnswer"] = nlohmann::json::parse(import_answer_schema);
  const nlohmann::json paths = nlohmann::json::parse(keep_paths);
  for (const auto& [path, operations] : paths.items())
    doc["paths"][path].update(operations);
  doc["components"]["schemas"]["Job"]["properties"].update(nlohmann::json::parse(keep_job_fields));
  doc["components"]["schemas"]["Study"]["properties"].update(
      {{"tags", {{"type", "array"}, {"items", {{"type", "string"}}}}},
       {"note", {{"type", "string"}, {"description", "free text its owner keeps with it (PATCH)"}}},
       {"archived_at",
        {{"type", "string"},
         {"nullable", true},
         {"description", "when it was archived; null = listed"}}}});
}

} // namespace slipfront::server
