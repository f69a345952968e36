-- wrk script: POST the same tiny job again and again (after the first run these are cache
-- hits: validation, hash lookup and one committed INSERT each, no new simulation).
wrk.method = "POST"
wrk.headers["Content-Type"] = "application/json"
wrk.body = '{"name": "load", "geometry": {"nodes_per_meter": 5}, "time": {"duration": 2.0}}'

done = function(summary, latency, requests)
  local codes = 0
  io.write(string.format("non-2xx/3xx: %d\n", summary.errors.status))
end
