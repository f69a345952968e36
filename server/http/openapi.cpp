// The OpenAPI 3.0 description served at GET /api/v1/openapi.json.
#include "api/job_schema.hpp"

#include "server/core/priority.hpp"
#include "server/http/handlers.hpp"
#include "solver/simulation.hpp"

#include <map>
#include <string>

namespace slipfront::server {

namespace {
const char* document = R"json({
  "openapi": "3.0.3",
  "info": {
    "title": "slipfront",
    "version": "the code's: added by openapi_document()",
    "description": "Simulation service for frictional interface rupture (Kammer et al. 2014) by two methods: the explicit finite-element method of the paper (method \"fe\", one or two elastic blocks) and the spectral boundary-integral method (method \"spectral_bi\", elastic half-spaces). Submit jobs, follow them, fetch their metrics, slip fronts, interface fields and HDF5 results; run studies over L and n_d; start from presets. Every GET also answers HEAD (same status and headers, no body). Request bodies are JSON: another Content-Type is answered 415. A method a path does not take is answered 405 with Allow. Guide: docs/server.md."
  },
  "servers": [{"url": "/"}],
  "tags": [
    {"name": "jobs", "description": "Submit, list, search, export and cancel jobs; the job schema and defaults"},
    {"name": "results", "description": "What a finished job produced: metrics, front, interface fields, stations, the HDF5 file and its XDMF sidecar; the length fit of one point's record (paper Sec. 6)"},
    {"name": "studies", "description": "Grids and convergence studies over L and n_d, their maps and critical lengths"},
    {"name": "presets", "description": "The standard scenes and examples a job may start from"},
    {"name": "ops", "description": "Health, Prometheus metrics and this document"}
  ],
  "components": {
    "securitySchemes": {"bearer": {"type": "http", "scheme": "bearer",
      "description": "Needed to submit and cancel when the server runs with --token-file."}},
    "parameters": {
      "id": {"name": "id", "in": "path", "required": true,
             "schema": {"type": "string", "pattern": "^[0-9a-f]{32}$"}}
    },
    "schemas": {
      "Problem": {"type": "object", "description": "application/problem+json (RFC 9457)",
        "properties": {"type": {"type": "string"}, "title": {"type": "string"},
          "status": {"type": "integer"}, "detail": {"type": "string"},
          "instance": {"type": "string"},
          "errors": {"type": "array", "items": {"type": "object", "properties": {
            "pointer": {"type": "string", "description": "JSON pointer of the bad field"},
            "reason": {"type": "string"}}}}}},
      "JobSpec": {"description": "generated from the job schema (api/job_schema.hpp) by openapi_document()"},
      "FieldSlice": {"type": "object", "properties": {"id": {"type": "string"}, "field": {"type": "string"},
        "units": {"type": "object", "properties": {"values": {"type": "string"}, "x1": {"type": "string"}, "time": {"type": "string"}}},
        "shape": {"type": "array", "items": {"type": "integer"}, "description": "[n_time, n_x1] returned"},
        "source_shape": {"type": "array", "items": {"type": "integer"}, "description": "[n_samples, n_nodes] of the dataset"},
        "stride": {"type": "object", "properties": {"time": {"type": "integer"}, "x1": {"type": "integer"}}},
        "first_index": {"type": "object", "properties": {"time": {"type": "integer"}, "x1": {"type": "integer"}}},
        "x1": {"type": "array", "items": {"type": "number"}}, "time": {"type": "array", "items": {"type": "number"}},
        "values": {"type": "array", "items": {"type": "array", "items": {"type": "number", "nullable": true}}},
        "min": {"type": "number", "nullable": true}, "max": {"type": "number", "nullable": true}}},
      "StationSeries": {"type": "object", "description": "The on-fault stations of a result file (docs/hdf5-layout.md \"/stations\"); the series are [n_samples, n_stations] as in the file, null for NaN.",
        "properties": {"id": {"type": "string"},
        "units": {"type": "object", "additionalProperties": {"type": "string"}},
        "x1": {"type": "array", "items": {"type": "number"}, "description": "m, the stations as the job lists them"},
        "rupture_threshold": {"type": "number", "description": "m/s"},
        "rupture_time": {"type": "array", "items": {"type": "number", "nullable": true}, "description": "s, first |V| > rupture_threshold; null if never"},
        "steps": {"type": "integer", "description": "time steps recorded in the file"},
        "stride": {"type": "integer", "description": "every stride-th step from the first is returned"},
        "time": {"type": "array", "items": {"type": "number"}},
        "slip_rate": {"type": "array", "items": {"type": "array", "items": {"type": "number", "nullable": true}}},
        "slip": {"type": "array", "items": {"type": "array", "items": {"type": "number", "nullable": true}}},
        "shear_traction": {"type": "array", "items": {"type": "array", "items": {"type": "number", "nullable": true}}},
        "normal_traction": {"type": "array", "items": {"type": "array", "items": {"type": "number", "nullable": true}}, "description": "Pa, negative in compression"}}},
      "StudyRequest": {"type": "object", "description": "docs/studies-api.md. Exactly one of grid, convergence, preset.",
        "properties": {"name": {"type": "string"}, "tags": {"type": "array", "items": {"type": "string"}},
          "base": {"$ref": "#/components/schemas/JobSpec"},
          "grid": {"type": "object", "properties": {"L": {"type": "array", "items": {"type": "number"}}, "n_d": {"type": "array", "items": {"type": "number"}}}},
          "convergence": {"type": "object", "properties": {"L": {"type": "array", "items": {"type": "number"}},
            "n_d": {"type": "array", "items": {"type": "number"}, "default": [10, 20, 40, 80, 160]}, "n_d_max": {"type": "number"}}},
          "preset": {"type": "string", "enum": ["failure_regimes"]},
          "priority": {"description": "server/core/priority.hpp: added by openapi_document()"}, "fresh": {"type": "boolean"}}},
      "LengthFitRequest": {"type": "object", "required": ["record"], "additionalProperties": false,
        "description": "docs/length-fit.md. Units: time s, slip_rate m/s, contact_pressure Pa (> 0 in compression), frictional_stress Pa. A record has 32 to 200000 samples (1000000 data rows in a CSV), within the server's body limit.",
        "properties": {
          "record": {"description": "an object of four equal-length arrays, or CSV text with a header naming the columns (or the stations CSV of GET /api/v1/jobs/{id}/stations.csv as it is)",
            "oneOf": [{"type": "object", "required": ["time", "slip_rate", "contact_pressure", "frictional_stress"], "additionalProperties": false,
              "properties": {"time": {"type": "array", "items": {"type": "number"}}, "slip_rate": {"type": "array", "items": {"type": "number"}},
                "contact_pressure": {"type": "array", "items": {"type": "number"}}, "frictional_stress": {"type": "array", "items": {"type": "number"}}}},
              {"type": "string"}]},
          "v_star": {"type": "number", "exclusiveMinimum": 0, "maximum": 1e6, "default": 1e-4, "description": "V* [m/s]; the start of its fit with fit_v_star"},
          "fit_v_star": {"type": "boolean", "default": false},
          "mu": {"type": "number", "exclusiveMinimum": 0, "maximum": 100, "description": "the friction coefficient; fitted when absent"},
          "station_x1": {"type": "number", "description": "the station of a stations CSV that holds several [m]"},
          "slip_threshold": {"type": "number", "minimum": 0, "maximum": 1e6, "description": "|V| [m/s] from which a sample slips; 1 % of the peak |V| when absent"}}},
      "StudyRun": {"type": "object", "properties": {"job_id": {"type": "string"}, "regime": {"type": "string"},
        "L": {"type": "number"}, "n_d": {"type": "number"}, "job_status": {"type": "string"},
        "outcome": {"type": "string", "nullable": true}, "cached_from": {"type": "string", "nullable": true},
        "convergence": {"type": "object", "properties": {
          "status": {"type": "string", "enum": ["converged", "not_converged", "unknown", "diverged", "pending", "failed"]},
          "partner_n_d": {"type": "number", "nullable": true},
          "changes": {"type": "object", "properties": {"propagation_distance": {"type": "number", "nullable": true}, "arrival_time": {"type": "number", "nullable": true}}},
          "reason": {"type": "string"}}}}},
      "Study": {"type": "object", "properties": {"id": {"type": "string"}, "name": {"type": "string"},
        "kind": {"type": "string", "enum": ["grid", "convergence", "failure_regimes"]},
        "status": {"type": "string", "enum": ["running", "finished", "cancelled"]},
        "progress": {"type": "object", "properties": {"done": {"type": "integer"}, "total": {"type": "integer"}, "fraction": {"type": "number"}}},
        "scene_hash": {"type": "string"}, "L_c": {"type": "number", "nullable": true},
        "companion_label": {"type": "string", "description": "what an L search's unregularised runs are called: plain Coulomb, or the law without regularisation"},
        "spectral_critical_length": {"type": "number", "nullable": true},
        "answer": {"type": "object", "description": "the headline answer (docs/studies.md \"The answer\"): {state, verdict, meaning, certainty, others: [{label, value, unit}]}"},
        "runs": {"type": "array", "items": {"$ref": "#/components/schemas/StudyRun"}},
        "critical_length": {"type": "object"}, "convergence_map": {"type": "object"},
        "refinement": {"type": "object", "description": "convergence studies: the plan per L"},
        "regimes": {"type": "array", "description": "failure_regimes: one entry per regime with its map and finding"}}},
      "Progress": {"type": "object", "properties": {"fraction": {"type": "number"},
        "time": {"type": "number"}, "duration": {"type": "number"}, "steps": {"type": "integer"},
        "eta_s": {"type": "number", "nullable": true}, "updated_at": {"type": "string", "nullable": true}}},
      "Job": {"type": "object", "properties": {
        "id": {"type": "string"},
        "status": {"type": "string", "enum": ["queued", "running", "succeeded", "failed", "cancelled"]},
        "name": {"type": "string"}, "tags": {"type": "array", "items": {"type": "string"}},
        "spec": {"type": "object"}, "spec_sha256": {"type": "string"},
        "submitted_by": {"type": "string", "nullable": true}, "priority": {"type": "integer"},
        "created_at": {"type": "string"}, "started_at": {"type": "string", "nullable": true},
        "finished_at": {"type": "string", "nullable": true},
        "progress": {"$ref": "#/components/schemas/Progress"},
        "metrics": {"type": "object", "nullable": true}, "error": {"type": "string", "nullable": true},
        "wall_time_s": {"type": "number", "nullable": true}, "code_version": {"type": "string", "nullable": true},
        "host": {"type": "string", "nullable": true},
        "result": {"type": "object", "nullable": true, "properties": {"url": {"type": "string"},
          "size": {"type": "integer"}, "sha256": {"type": "string"}}},
        "cached_from": {"type": "string", "nullable": true},
        "memory_estimate_bytes": {"type": "number"}, "attempts": {"type": "integer"},
        "scene_hash": {"type": "string", "nullable": true}, "study_id": {"type": "string", "nullable": true},
        "executor": {"type": "string", "nullable": true, "enum": ["local", "slurm", null], "description": "where it ran (null until it started)"},
        "slurm_job_id": {"type": "string", "nullable": true, "description": "its SLURM job (executor slurm)"},
        "slurm_state": {"type": "string", "nullable": true, "description": "last SLURM state seen, with the reason: PENDING (Resources), RUNNING on node7, TIMEOUT (TimeLimit)"},
        "warnings": {"type": "array", "items": {"$ref": "#/components/schemas/Warning"}, "description": "what the validation warned about when the job was accepted (docs/api-job-spec.md \"Warnings\")"},
        "provenance": {"type": "array", "nullable": true, "items": {"$ref": "#/components/schemas/ValueSource"}, "description": "every number with a unit the run takes and where it came from; null for jobs accepted before it was kept"},
        "estimate": {"type": "object", "nullable": true, "description": "the cost estimate before the run (docs/performance.md \"Cost estimate\")"},
        "resolution": {"type": "object", "nullable": true, "description": "the law's static process zone [m], the elements across it and its formula; null for a law that does not weaken (docs/api-job-spec.md \"Warnings\")"},
        "links": {"type": "object"}}},
      "Warning": {"type": "object", "properties": {"pointer": {"type": "string"}, "message": {"type": "string"}}},
      "ValueSource": {"type": "object", "properties": {"pointer": {"type": "string"}, "value": {"type": "number"},
        "unit": {"type": "string"}, "source": {"type": "string", "description": "given, preset NAME, default (the paper's scene) or derived: how"}}},
      "Validation": {"type": "object", "properties": {"valid": {"type": "boolean"}, "spec": {"type": "object"},
        "errors": {"type": "array", "description": "an invalid job: every error, as POST /jobs would give them", "items": {"type": "object", "properties": {"pointer": {"type": "string"}, "reason": {"type": "string"}}}},
        "spec_sha256": {"type": "string"}, "memory_estimate_bytes": {"type": "number"},
        "warnings": {"type": "array", "items": {"$ref": "#/components/schemas/Warning"}},
        "provenance": {"type": "array", "items": {"$ref": "#/components/schemas/ValueSource"}},
        "resolution": {"type": "object", "nullable": true},
        "estimate": {"type": "object", "nullable": true}}}
    },
    "responses": {
      "Problem": {"description": "Error", "content": {"application/problem+json": {"schema": {"$ref": "#/components/schemas/Problem"}}}},
      "Study": {"description": "The study", "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Study"}}}},
      "Job": {"description": "The job", "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Job"}}}},
      "Unavailable": {"description": "Service unavailable: the storage refused a write or a read (disk full, I/O error, database busy), the connection cap was reached, --max-exports exports or --max-fits length fits are running, archives not yet sent hold --max-export-bytes or the disk would fall below --min-free-bytes (exports, imports), or the server is draining; retry after Retry-After seconds",
        "headers": {"Retry-After": {"schema": {"type": "integer"}}},
        "content": {"application/problem+json": {"schema": {"$ref": "#/components/schemas/Problem"}}}}
    }
  },
  "paths": {
    "/api/v1/jobs": {
      "post": {"summary": "Submit a job", "security": [{"bearer": []}],
        "parameters": [
          {"name": "fresh", "in": "query", "schema": {"type": "boolean"}, "description": "run even if an identical succeeded job exists"},
          {"name": "priority", "in": "query", "schema": {"description": "server/core/priority.hpp: added by openapi_document()"}},
          {"name": "Idempotency-Key", "in": "header", "schema": {"type": "string", "maxLength": 200}, "description": "a retried POST with the same key returns the first job (200)"}],
        "requestBody": {"required": true, "content": {"application/json": {"schema": {"$ref": "#/components/schemas/JobSpec"}}}},
        "responses": {
          "201": {"description": "Created (queued, or reused: cache = hit, cached_from set); Location names the job", "headers": {"Location": {"schema": {"type": "string"}}}, "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Job"}}}},
          "200": {"$ref": "#/components/responses/Job"},
          "400": {"$ref": "#/components/responses/Problem"}, "401": {"$ref": "#/components/responses/Problem"},
          "413": {"$ref": "#/components/responses/Problem"}, "422": {"$ref": "#/components/responses/Problem"},
          "503": {"description": "Queue full, shutting down, storage unavailable (disk full, I/O error) or connection cap reached (Retry-After)", "headers": {"Retry-After": {"schema": {"type": "integer"}}}}}},
      "get": {"summary": "List, search and export jobs (newest first, or by sort)",
        "parameters": [
          {"name": "where", "in": "query", "schema": {"type": "string"}, "example": "friction.L<1e-4; metrics.arrest_position>12", "description": "conditions FIELD OP VALUE joined by ';' or 'and'; OP one of = != < <= > >=; FIELD a job column (id, name, status, method, outcome, tag (or tags), submitted_by, created_at, started_at, finished_at, study_id, scene_hash, spec_sha256, code_version, convergence_status, wall_time_s, memory_estimate_bytes, attempts, priority, L, n_d), any spec field (friction.L or spec.friction.L) or metrics.NAME (metrics.rupture_speed.max); values are numbers, true/false, or text (quote with ' or \" if it holds spaces or ';'). A run without the field never matches. docs/server.md"},
          {"name": "sort", "in": "query", "schema": {"type": "string"}, "example": "-metrics.arrest_position,friction.L", "description": "comma-separated fields as in where, '-' for descending; nulls last; then newest first"},
          {"name": "format", "in": "query", "schema": {"type": "string", "enum": ["json", "csv", "ndjson"], "default": "json"}, "description": "csv or ndjson: the flat run table (job columns, the provenance columns spec_sha256, scene_hash, code_version, result_sha256, result_size_bytes, result_url, spec.*, metrics.*, convergence_status), limit up to 100000 (default 10000), the next page in the Link header (rel=next)"},
          {"name": "status", "in": "query", "schema": {"type": "string"}, "description": "comma-separated statuses"},
          {"name": "tag", "in": "query", "schema": {"type": "string"}},
          {"name": "name", "in": "query", "schema": {"type": "string"}},
          {"name": "outcome", "in": "query", "schema": {"type": "string", "enum": ["arrested", "running_at_end", "no_rupture", "diverged"]}},
          {"name": "submitted_by", "in": "query", "schema": {"type": "string"}},
          {"name": "spec_sha256", "in": "query", "schema": {"type": "string"}},
          {"name": "scene_hash", "in": "query", "schema": {"type": "string"}, "description": "jobs of one convergence map (spec without L and n_d)"},
          {"name": "study_id", "in": "query", "schema": {"type": "string"}, "description": "jobs submitted by one study"},
          {"name": "L_min", "in": "query", "schema": {"type": "number"}},
          {"name": "L_max", "in": "query", "schema": {"type": "number"}},
          {"name": "n_d_min", "in": "query", "schema": {"type": "number"}},
          {"name": "n_d_max", "in": "query", "schema": {"type": "number"}},
          {"name": "limit", "in": "query", "schema": {"type": "integer", "minimum": 1, "maximum": 100000, "default": 50}, "description": "json: 1..1000 (default 50); csv/ndjson: 1..100000 (default 10000)"},
          {"name": "cursor", "in": "query", "schema": {"type": "string"}, "description": "next_cursor of the previous page (with sort: an offset cursor 'oN')"},
          {"name": "fields", "in": "query", "schema": {"type": "string"}, "description": "comma-separated top-level fields to keep (id is always kept)"}],
        "responses": {"200": {"description": "A page", "headers": {"Link": {"schema": {"type": "string"}, "description": "csv/ndjson: <next page>; rel=\"next\""}},
          "content": {"application/json": {"schema": {"type": "object", "properties": {
          "jobs": {"type": "array", "items": {"$ref": "#/components/schemas/Job"}}, "count": {"type": "integer"},
          "next_cursor": {"type": "string", "nullable": true}, "next": {"type": "string", "nullable": true}}}},
          "text/csv": {"schema": {"type": "string"}}, "application/x-ndjson": {"schema": {"type": "string"}}}},
          "400": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/jobs/{id}": {
      "get": {"summary": "A job: status, progress, spec, metrics, timing",
        "parameters": [{"$ref": "#/components/parameters/id"},
          {"name": "fields", "in": "query", "schema": {"type": "string"}}],
        "responses": {"200": {"$ref": "#/components/responses/Job"}, "404": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/jobs/{id}/cancel": {
      "post": {"summary": "Cancel a job (queued: 200 at once; running: 202, it ends cancelled within about a second; finishing or finished: 409)", "security": [{"bearer": []}],
        "parameters": [{"$ref": "#/components/parameters/id"}],
        "responses": {"200": {"$ref": "#/components/responses/Job"}, "202": {"$ref": "#/components/responses/Job"},
          "401": {"$ref": "#/components/responses/Problem"}, "403": {"$ref": "#/components/responses/Problem"},
          "404": {"$ref": "#/components/responses/Problem"}, "409": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/jobs/{id}/result.h5": {
      "get": {"summary": "The HDF5 result file (strong ETag = sha256; Range; If-None-Match)",
        "parameters": [{"$ref": "#/components/parameters/id"},
          {"name": "Range", "in": "header", "schema": {"type": "string"}},
          {"name": "If-None-Match", "in": "header", "schema": {"type": "string"}},
          {"name": "If-Range", "in": "header", "schema": {"type": "string"}}],
        "responses": {"200": {"description": "The file", "content": {"application/x-hdf5": {}}},
          "206": {"description": "One byte range", "content": {"application/x-hdf5": {}}},
          "304": {"description": "Not modified"},
          "404": {"$ref": "#/components/responses/Problem"}, "409": {"$ref": "#/components/responses/Problem"},
          "410": {"description": "The job succeeded but its result file was deleted from the data dir, is damaged (another size or SHA-256 than stored) or is not a regular file; an identical new job runs again", "content": {"application/problem+json": {"schema": {"$ref": "#/components/schemas/Problem"}}}},
          "416": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/jobs/{id}/result.xdmf": {
      "get": {"summary": "The XDMF sidecar of the result file: the interface fields on the x1-t plane for ParaView/VisIt; it refers to the HDF5 file as ID.h5 (save both in one directory)",
        "parameters": [{"$ref": "#/components/parameters/id"}],
        "responses": {"200": {"description": "XDMF 3", "content": {"application/xml": {}}},
          "404": {"$ref": "#/components/responses/Problem"}, "409": {"$ref": "#/components/responses/Problem"},
          "410": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/jobs/{id}/metrics": {
      "get": {"summary": "The metrics of the run as JSON (docs/metrics.md)", "parameters": [{"$ref": "#/components/parameters/id"}],
        "responses": {"200": {"description": "Metrics", "content": {"application/json": {}}},
          "404": {"$ref": "#/components/responses/Problem"}, "409": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/jobs/{id}/front": {
      "get": {"summary": "The slip front: x1, arrival_time, rupture_speed (null where undefined)", "parameters": [{"$ref": "#/components/parameters/id"}],
        "responses": {"200": {"description": "Front", "content": {"application/json": {}}},
          "404": {"$ref": "#/components/responses/Problem"}, "409": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/jobs/{id}/fields/{name}": {
      "get": {"summary": "A window of one /interface field of the HDF5 result as JSON, decimated to a point budget (docs/server.md, docs/hdf5-layout.md)",
        "description": "Rows are samples in time, columns nodes in x1 (time-major, as in the file). The samples (nodes) kept are those with t (x1) in [min, max]; a window holding none keeps the one nearest its middle, so x1_min = x1_max = X gives the history V(t) at the node nearest X. When n_time * n_x1 exceeds max_points, every k-th row and column is kept (one stride for both axes where possible; values are the file's, not averaged). NaN is null. GET answers carry a weak ETag.",
        "parameters": [{"$ref": "#/components/parameters/id"},
          {"name": "name", "in": "path", "required": true, "schema": {"type": "string", "enum": ["slip_velocity", "slip", "shear_traction", "contact_pressure", "strength", "state"]}},
          {"name": "x1_min", "in": "query", "schema": {"type": "number"}, "description": "m; default: the first node"},
          {"name": "x1_max", "in": "query", "schema": {"type": "number"}, "description": "m; >= x1_min; default: the last node"},
          {"name": "t_min", "in": "query", "schema": {"type": "number"}, "description": "s; default: the first sample"},
          {"name": "t_max", "in": "query", "schema": {"type": "number"}, "description": "s; >= t_min; default: the last sample"},
          {"name": "max_points", "in": "query", "schema": {"type": "integer", "minimum": 1, "maximum": 4000000, "default": 200000}, "description": "budget for n_time * n_x1"}],
        "responses": {"200": {"description": "The slice", "content": {"application/json": {"schema": {"$ref": "#/components/schemas/FieldSlice"}}}},
          "400": {"$ref": "#/components/responses/Problem"}, "404": {"$ref": "#/components/responses/Problem"},
          "409": {"$ref": "#/components/responses/Problem"}, "410": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/jobs/{id}/stations": {
      "get": {"summary": "The job's on-fault stations as JSON: positions, rupture times, threshold and the four series (slip rate, slip, shear and normal traction) within a sample budget (docs/server.md)",
        "description": "Every recorded step when there are at most max_samples, else every k-th step from the first, k = ceil(steps / max_samples): the file's values, not averaged (the CSV has every step). GET answers carry a weak ETag.",
        "parameters": [{"$ref": "#/components/parameters/id"},
          {"name": "max_samples", "in": "query", "schema": {"type": "integer", "minimum": 1, "maximum": 1000000, "default": 10000}, "description": "at most this many time samples"}],
        "responses": {"200": {"description": "The stations", "content": {"application/json": {"schema": {"$ref": "#/components/schemas/StationSeries"}}}},
          "400": {"$ref": "#/components/responses/Problem"}, "404": {"$ref": "#/components/responses/Problem"},
          "409": {"$ref": "#/components/responses/Problem"}, "410": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/jobs/{id}/stations.csv": {
      "get": {"summary": "The job's on-fault stations, every recorded step, as CSV in the long format (docs/hdf5-layout.md, \"Stations as CSV\")",
        "description": "Comment lines first (# units, the rupture threshold, each station's rupture time; nan: never), then the header station_x1,time,slip,slip_rate,shear_traction,normal_traction and one row per station and time step, station by station. Units: m, s, m, m/s, Pa, Pa; normal_traction is negative in compression. Read with pandas.read_csv(url, comment='#').",
        "parameters": [{"$ref": "#/components/parameters/id"}],
        "responses": {"200": {"description": "The stations as CSV", "content": {"text/csv": {"schema": {"type": "string"}}}},
          "404": {"$ref": "#/components/responses/Problem"}, "409": {"$ref": "#/components/responses/Problem"},
          "410": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/jobs/validate": {
      "post": {"summary": "Check a job as POST /jobs would, without submitting it: its canonical spec, warnings, the source of each number with a unit, and the cost estimate (the web form asks it while one types); no token is needed",
        "requestBody": {"required": true, "content": {"application/json": {"schema": {"$ref": "#/components/schemas/JobSpec"}}}},
        "responses": {"200": {"description": "The answer: a valid job with its spec, warnings, provenance and estimate; an invalid one as {valid: false, errors: [{pointer, reason}]} (what POST /jobs refuses with 422)", "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Validation"}}}},
          "400": {"$ref": "#/components/responses/Problem"}, "413": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/job-defaults": {
      "get": {"summary": "The canonical spec of an empty job of a method: every field with its default (the web view's submit form starts from it)",
        "parameters": [{"name": "method", "in": "query", "schema": "the methods: added by openapi_document()"}],
        "responses": {"200": {"description": "{method, spec, memory_estimate_bytes}", "content": {"application/json": {}}},
          "400": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/presets": {
      "get": {"summary": "The presets a job may start from: the field's standard scenes (presets/) and the example jobs (examples/); a job names one with \"preset\": NAME (docs/presets.md)",
        "responses": {"200": {"description": "{presets: [{name, origin, title, description, reference, spec}]}", "content": {"application/json": {}}}}}
    },
    "/api/v1/presets/{name}": {
      "get": {"summary": "One preset: {name, origin, title, description, reference, spec}",
        "parameters": [{"name": "name", "in": "path", "required": true, "schema": {"type": "string"}}],
        "responses": {"200": {"description": "the preset", "content": {"application/json": {}}}, "404": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/length-fits": {
      "post": {"summary": "The experimentalist's procedure of the paper (Sec. 6) on the record of one interface point: the fitted length L_m of the simplified Prakash-Clifton law with its 95 % interval, the measured critical frequency f_m, the contact pressure's spectrum and the verdict (L_m is the physical length, or the event only bounds it, by its own critical length); nothing is stored, no token is needed (docs/length-fit.md)",
        "requestBody": {"required": true, "content": {"application/json": {"schema": {"$ref": "#/components/schemas/LengthFitRequest"}}}},
        "responses": {"200": {"description": "{law, record, fit, critical_frequency, spectrum, verdict, series} (docs/length-fit.md \"The answer\")", "content": {"application/json": {}}},
          "400": {"$ref": "#/components/responses/Problem"}, "413": {"$ref": "#/components/responses/Problem"},
          "422": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/studies": {
      "post": {"summary": "Create a study: its runs are ordinary jobs (reused when identical results exist); the study and its first runs are stored in one transaction", "security": [{"bearer": []}],
        "parameters": [
          {"name": "Idempotency-Key", "in": "header", "schema": {"type": "string", "maxLength": 200}, "description": "a retried POST with the same key and body returns the first study (200, Idempotent-Replayed: true); another body with the key is a 422"}],
        "requestBody": {"required": true, "content": {"application/json": {"schema": {"$ref": "#/components/schemas/StudyRequest"}}}},
        "responses": {"201": {"description": "Created; Location names the study", "headers": {"Location": {"schema": {"type": "string"}}},
            "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Study"}}}},
          "200": {"description": "Replayed: the study an earlier request with the same Idempotency-Key created", "headers": {"Idempotent-Replayed": {"schema": {"type": "string"}}},
            "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Study"}}}},
          "400": {"$ref": "#/components/responses/Problem"}, "401": {"$ref": "#/components/responses/Problem"},
          "422": {"$ref": "#/components/responses/Problem"}, "503": {"$ref": "#/components/responses/Unavailable"}}},
      "get": {"summary": "List studies, newest first (summaries)",
        "parameters": [{"name": "status", "in": "query", "schema": {"type": "string", "enum": ["running", "finished", "cancelled"]}},
          {"name": "limit", "in": "query", "schema": {"type": "integer", "minimum": 1, "maximum": 1000, "default": 50}},
          {"name": "cursor", "in": "query", "schema": {"type": "string"}},
          {"name": "archived", "in": "query", "schema": {"type": "string", "enum": ["exclude", "include", "only"], "default": "exclude"}, "description": "archived studies: left out (default), listed too, or alone"}],
        "responses": {"200": {"description": "A page: {studies, count, next_cursor, next}"}, "400": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/studies/{id}": {
      "get": {"summary": "A study: status, progress, runs with convergence status, L_c, spectral estimate, convergence map",
        "parameters": [{"$ref": "#/components/parameters/id"}],
        "responses": {"200": {"$ref": "#/components/responses/Study"}, "404": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/studies/{id}/cancel": {
      "post": {"summary": "Cancel a running study: no further runs; its queued runs are cancelled, its running runs asked to stop (their results so far stay)",
        "security": [{"bearer": []}], "parameters": [{"$ref": "#/components/parameters/id"}],
        "responses": {"200": {"description": "Cancelled; every unfinished run was queued. The study with cancelled_jobs, cancel_requested_jobs"},
          "202": {"description": "Cancelled; running runs stop at their next step (cancel_requested_jobs)"},
          "400": {"$ref": "#/components/responses/Problem"}, "401": {"$ref": "#/components/responses/Problem"}, "403": {"$ref": "#/components/responses/Problem"},
          "404": {"$ref": "#/components/responses/Problem"}, "409": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/studies/{id}/speed-accuracy": {
      "get": {"summary": "Per run: wall time, memory estimate, errors against the reference run of its L (arrival time, propagation distance, L2 of the slip velocity at the spectrum probe)",
        "parameters": [{"$ref": "#/components/parameters/id"}],
        "responses": {"200": {"description": "{study_id, runs, probe, reference}"}, "404": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/convergence-map": {
      "get": {"summary": "The convergence map and L_c of every succeeded/failed job of a scene, whoever submitted it",
        "parameters": [{"name": "scene", "in": "query", "schema": {"type": "string", "pattern": "^[0-9a-f]{64}$"}},
          {"name": "study", "in": "query", "schema": {"type": "string"}, "description": "take the scene of this study"}],
        "responses": {"200": {"description": "{scene_hash, count, runs, convergence_map, critical_length}"},
          "400": {"$ref": "#/components/responses/Problem"}, "404": {"$ref": "#/components/responses/Problem"}}}
    },
    "/api/v1/schema/job.json": {"get": {"summary": "The job schema (JSON Schema 2020-12): every field with its type, range, default, unit, meaning and methods (x-unit, x-methods)", "responses": {"200": {"description": "JSON Schema", "content": {"application/json": {"schema": {"type": "object"}}}}}}},
    "/api/v1/openapi.json": {"get": {"summary": "This document", "responses": {"200": {"description": "OpenAPI 3"}}}},
    "/healthz": {"get": {"summary": "Liveness and readiness", "responses": {"200": {"description": "ok"}, "503": {"description": "draining, database error, or degraded: free space below --min-free-bytes or a storage error in the last 60 s (storage: free_bytes, last_error); with Retry-After only when the connection cap answered", "headers": {"Retry-After": {"schema": {"type": "integer"}, "required": false}}}}}},
    "/metrics": {"get": {"summary": "Prometheus metrics: queue depth, running, jobs by status, run durations, HTTP requests", "responses": {"200": {"description": "text/plain; version=0.0.4"}}}}
  }
})json";
// The one range of a priority (server/core/priority.hpp), wherever the document takes one.
nlohmann::json priority_schema() {
  return {{"type", "integer"}, {"minimum", lowest_priority}, {"maximum", highest_priority}};
}

// The tag of each path (the groups of the API docs page); every path has one.
const std::map<std::string, std::string>& path_tags() {
  static const std::map<std::string, std::string> tags = {
      {"/api/v1/jobs", "jobs"},
      {"/api/v1/jobs/{id}", "jobs"},
      {"/api/v1/jobs/{id}/cancel", "jobs"},
      {"/api/v1/jobs/{id}/archive", "jobs"},
      {"/api/v1/jobs/{id}/restore", "jobs"},
      {"/api/v1/exports", "jobs"},
      {"/api/v1/imports", "jobs"},
      {"/api/v1/job-defaults", "jobs"},
      {"/api/v1/jobs/validate", "jobs"},
      {"/api/v1/schema/job.json", "jobs"},
      {"/api/v1/jobs/{id}/result.h5", "results"},
      {"/api/v1/jobs/{id}/result.xdmf", "results"},
      {"/api/v1/jobs/{id}/metrics", "results"},
      {"/api/v1/jobs/{id}/front", "results"},
      {"/api/v1/jobs/{id}/fields/{name}", "results"},
      {"/api/v1/jobs/{id}/stations", "results"},
      {"/api/v1/jobs/{id}/stations.csv", "results"},
      {"/api/v1/length-fits", "results"},
      {"/api/v1/studies", "studies"},
      {"/api/v1/studies/{id}", "studies"},
      {"/api/v1/studies/{id}/cancel", "studies"},
      {"/api/v1/studies/{id}/archive", "studies"},
      {"/api/v1/studies/{id}/export", "studies"},
      {"/api/v1/studies/{id}/restore", "studies"},
      {"/api/v1/studies/{id}/speed-accuracy", "studies"},
      {"/api/v1/convergence-map", "studies"},
      {"/api/v1/presets", "presets"},
      {"/api/v1/presets/{name}", "presets"},
      {"/api/v1/openapi.json", "ops"},
      {"/healthz", "ops"},
      {"/metrics", "ops"},
  };
  return tags;
}

} // namespace

// What holds for every operation, added here rather than repeated in the text above:
// - its tag (path_tags);
// - any request may get a 503 with Retry-After: the connection cap (listener.cpp) answers it
//   before routing, and a storage error in any handler becomes one (router.cpp);
// - an operation with a JSON body answers 415 to another Content-Type (router.cpp).
// HEAD is not listed beside each GET (it would double every row of the API docs page); the
// description says that every GET answers it (router.cpp).
nlohmann::json openapi_document() {
  nlohmann::json doc = nlohmann::json::parse(document);
  doc["info"]["version"] = code_version(); // what `slipfront --version` prints
  // The job body: the job schema, plus the two submission options the server reads and
  // removes before validation (docs/server.md).
  nlohmann::json job = api::job_json_schema();
  job.erase("$schema");
  job.erase("$id");
  job["properties"]["fresh"] = {
      {"type", "boolean"},
      {"default", false},
      {"description", "submission option: run again even if an identical job succeeded"}};
  job["properties"]["priority"] = priority_schema();
  job["properties"]["priority"]["default"] = 0;
  job["properties"]["priority"]["description"] = "submission option: higher runs first";
  doc["components"]["schemas"]["JobSpec"] = job;
  doc["components"]["schemas"]["StudyRequest"]["properties"]["priority"] = priority_schema();
  for (auto& parameter : doc["paths"]["/api/v1/jobs"]["post"]["parameters"])
    if (parameter["name"] == "priority") parameter["schema"] = priority_schema();
  // The methods, from the registry (solver/methods.hpp) as the job schema has them.
  for (auto& parameter : doc["paths"]["/api/v1/job-defaults"]["get"]["parameters"])
    if (parameter["name"] == "method")
      parameter["schema"] = {{"type", "string"},
                             {"enum", job["properties"]["method"]["enum"]},
                             {"default", job["properties"]["method"]["default"]}};
  add_keep_share_paths(doc); // openapi_keep.cpp
  const nlohmann::json unavailable = {{"$ref", "#/components/responses/Unavailable"}};
  const nlohmann::json unsupported = {
      {"description", "The body's Content-Type is not application/json (Accept names it)"},
      {"headers", {{"Accept", {{"schema", {{"type", "string"}}}}}}},
      {"content",
       {{"application/problem+json", {{"schema", {{"$ref", "#/components/schemas/Problem"}}}}}}}};
  for (auto& [path, operations] : doc["paths"].items()) {
    for (auto& [method, operation] : operations.items()) {
      operation["tags"] = {path_tags().at(path)};
      if (!operation["responses"].contains("503")) operation["responses"]["503"] = unavailable;
      if (operation.contains("requestBody") &&
          operation["requestBody"]["content"].contains("application/json"))
        operation["responses"]["415"] = unsupported;
    }
  }
  return doc;
}

} // namespace slipfront::server
