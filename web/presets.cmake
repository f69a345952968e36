# Writes the web view's built-in preset list (docs/web.md, "Presets") from the job files in
# examples/: [{"file": "<name>.json", "spec": <its JSON>}, ...], sorted by file name. Run by
# web/CMakeLists.txt at build time:  cmake -DEXAMPLES=dir -DOUT=file -P presets.cmake
file(GLOB examples ${EXAMPLES}/*.json)
list(SORT examples)
# Appended as one string, not a CMake list: the specs may hold ";" (list separators).
set(body "")
set(separator "")
foreach(path IN LISTS examples)
  file(READ ${path} spec)
  # A broken example stops the build here, naming the file, rather than the page.
  string(JSON kind ERROR_VARIABLE problem TYPE "${spec}")
  if(problem OR NOT kind STREQUAL "OBJECT")
    message(FATAL_ERROR "presets: ${path} is not a JSON object: ${problem}")
  endif()
  get_filename_component(name ${path} NAME)
  string(STRIP "${spec}" spec)
  string(APPEND body "${separator}{\"file\": \"${name}\", \"spec\": ${spec}}")
  set(separator ",\n")
endforeach()
file(WRITE ${OUT}.tmp "[\n${body}\n]\n")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUT}.tmp)
