# ctest "oracle:hull *": hull shaders as written (docs/gpu_lod.md "Your hull shader as written") through `fftess sweep`
# and `fftess check` on the local OpenGL driver (llvmpipe in CI).
#   CASE=example_NAME  the two scenes of docs/examples/hull/NAME.* (grid and tile rings, 40 flyover cameras): exit < 2,
#                  the GPU LOD section names the hull shader, and the verdict line is the one measured on llvmpipe
#                  (tests/oracle/data/hull/verdicts.txt: SCENE|VERDICT LINE)
#   CASE=twin      tests/oracle/data/hull/twin.tesc (a TCS whose control points arrive as a loop, its domain's u along
#                  +z) and twin.glsl (the same rule as a lodMain file, fftess's corner order): the same stats and verdict
#                  on tile rings, so control points, levels and edges are mapped right (a wrong lod.domain_u gives ten
#                  times the cracks); twin_es.tesc, the same TCS in GLSL ES 3.10, and
#                  twin_per_invocation.tesc (each invocation writes gl_TessLevelOuter[gl_InvocationID]) give the same
#                  findings
#   CASE=bad       the negative fixtures (tests/oracle/data/hull/*.toml): exit 2, every line before the last one
#                  diagnostic FILE:LINE:COL: error: MESSAGE, the expected ones among them, the last "fftess: error: ...";
#                  an evaluation shader whose spacing contradicts the scene, named at its layout
# No OpenGL context: a visible skip ("HULL-SKIPPED"), a failure when CI is set. Variables: FFTESS, SRC, CASE.
cmake_policy(SET CMP0054 NEW)
set(hull_examples ${SRC}/docs/examples/hull)
set(data ${SRC}/tests/oracle/data/hull)

function(skip why)
  if(DEFINED ENV{CI})
    message(FATAL_ERROR "hull_${CASE}: ${why} (CI is set: this must run)")
  endif()
  message("HULL-SKIPPED: ${why}")
endfunction()

# Runs fftess ARGS; sets rc, out, err in the caller; returns from the caller on a missing context (skip).
macro(run)
  execute_process(COMMAND ${FFTESS} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(err MATCHES "no OpenGL context for the GPU LOD")
    skip("${err}")
    return()
  endif()
endmacro()

# The lines of the sweep summary that count findings, and the verdict.
function(findings_of text var)
  string(REGEX MATCHALL "\n  (patches|edges checked|matches|T-junctions|cracks|holes|worst gap|all cracks) [^\n]*|\nverdict: [^\n]*"
         lines "${text}")
  set(${var} "${lines}" PARENT_SCOPE)
endfunction()

if(CASE MATCHES "^example_(.*)$")
  set(example ${CMAKE_MATCH_1})
  file(STRINGS ${data}/verdicts.txt expected REGEX "^${example}_(grid|rings)\\.toml\\|")
  list(LENGTH expected n)
  if(NOT n EQUAL 2)
    message(FATAL_ERROR "hull_${CASE}: ${data}/verdicts.txt has ${n} lines for ${example}, expected its grid and rings scenes")
  endif()
  foreach(line ${expected})
    string(FIND "${line}" "|" bar)
    string(SUBSTRING "${line}" 0 ${bar} scene)
    math(EXPR start "${bar} + 1")
    string(SUBSTRING "${line}" ${start} -1 verdict)
    run(sweep ${hull_examples}/${scene} --flyover 40 --threads 2)
    if(NOT rc LESS 2 OR NOT out MATCHES "GPU LOD +hull shader [^\n]*${scene}")
      string(REGEX REPLACE "_(grid|rings).toml$" "" shader "${scene}")
      if(NOT rc LESS 2 OR NOT out MATCHES "GPU LOD +hull shader [^\n]*${shader}")
        message(FATAL_ERROR "hull_${CASE}: ${scene}: exit ${rc}, no hull shader section: ${err}\n${out}")
      endif()
    endif()
    string(REGEX MATCH "verdict: [^\n]*" got "${out}")
    # The default sweep runs visible first: the same verdict on screen, fewer off-screen cracks looked for (the
    # count in the last parentheses); the full check (--no-visible-first) gives the measured line itself.
    string(REGEX REPLACE " \\([0-9]+ cracks off screen, not counted\\)$" "" got_on_screen "${got}")
    string(REGEX REPLACE " \\([0-9]+ cracks off screen, not counted\\)$" "" verdict_on_screen "${verdict}")
    if(NOT got_on_screen STREQUAL verdict_on_screen)
      message(FATAL_ERROR "hull_${CASE}: ${scene}: verdict\n  '${got}'\nexpected on screen (llvmpipe, verdicts.txt)\n  '${verdict}'")
    endif()
    run(sweep ${hull_examples}/${scene} --flyover 40 --threads 2 --no-visible-first)
    string(REGEX MATCH "verdict: [^\n]*" got "${out}")
    if(NOT got STREQUAL verdict)
      message(FATAL_ERROR "hull_${CASE}: ${scene}: verdict (--no-visible-first)\n  '${got}'\nexpected (llvmpipe, verdicts.txt)\n  '${verdict}'")
    endif()
  endforeach()
  if(example STREQUAL "frustum_heightmap") # docs/gpu_lod.md quotes this scene's [lod] block: it stays the file's
    file(READ ${hull_examples}/frustum_heightmap_grid.toml scene_text)
    string(FIND "${scene_text}" "[lod]\n" from)
    string(FIND "${scene_text}" "\n[tessellation]" to)
    math(EXPR length "${to} - ${from}")
    string(SUBSTRING "${scene_text}" ${from} ${length} block)
    string(STRIP "${block}" block)
    file(READ ${SRC}/docs/gpu_lod.md doc)
    string(FIND "${doc}" "${block}" quoted)
    if(quoted EQUAL -1)
      message(FATAL_ERROR "hull_${CASE}: docs/gpu_lod.md no longer quotes the [lod] block of frustum_heightmap_grid.toml")
    endif()
  endif()
  message("hull_${CASE}: ${n} scenes, each with its measured verdict")
elseif(CASE STREQUAL "twin")
  run(sweep ${data}/twin_tcs.toml --flyover 40 --threads 2)
  findings_of("${out}" tcs)
  set(tcs_rc ${rc})
  run(sweep ${data}/twin_lodmain.toml --flyover 40 --threads 2)
  findings_of("${out}" lodmain)
  if(NOT tcs_rc EQUAL rc OR NOT tcs STREQUAL lodmain OR NOT tcs MATCHES "cracks +[1-9]")
    message(FATAL_ERROR "hull_twin: the TCS and its lodMain twin differ (exit ${tcs_rc} vs ${rc}):\nTCS:${tcs}\nlodMain:${lodmain}")
  endif()
  run(sweep ${data}/twin_es.toml --flyover 40 --threads 2)
  findings_of("${out}" es)
  if(NOT es STREQUAL lodmain)
    message(FATAL_ERROR "hull_twin: the GLSL ES 3.10 TCS differs from its lodMain twin (exit ${rc}): ${err}\nES:${es}\nlodMain:${lodmain}")
  endif()
  run(sweep ${data}/twin_per_invocation.toml --flyover 40 --threads 2)
  findings_of("${out}" per_invocation)
  if(NOT per_invocation STREQUAL lodmain)
    message(FATAL_ERROR "hull_twin: the TCS writing gl_TessLevelOuter[gl_InvocationID] differs from its lodMain twin (exit ${rc}): ${err}\nTCS:${per_invocation}\nlodMain:${lodmain}")
  endif()
  message("hull_twin: the TCS (corners as a loop, u along +z) and the lodMain twin agree:${tcs}")
elseif(CASE STREQUAL "bad")
  # scene|expected diagnostic (a regex over one stderr line)
  set(cases
      "unbound_uniform.toml|unbound_uniform.tesc:8:15: error: uniform 'uLodBias' is not bound: add 'uLodBias' to \\[lod.uniforms\\]"
      "missing_sampler.toml|missing_sampler.tesc:11:19: error: sampler 'uHeightMap' is not bound: add uHeightMap = \"heightmap\""
      "partitioning_contradicts.toml|partitioning_contradicts.hlsl:47:1: error: \\[partitioning\\(\"integer\"\\)\\] contradicts the scene's tessellation.partitioning = \"fractional_odd\""
      "wrong_entry.toml|wrong_entry.toml:24:9: error: lod.entry 'TerrainHS' names no function in [^\n]*partitioning_contradicts.hlsl \\(hull shaders here: HS\\)"
      "syntax_error.toml|syntax_error.tesc:19:5: error: syntax error, unexpected IDENTIFIER, expecting COMMA or SEMICOLON"
      "include_error.toml|include/bad_level.glsl:5:42: error: 'uUndeclaredBias' : undeclared identifier"
      "include_missing.toml|include_missing.tesc:11:1: error: '#include' : Could not process include directive")
  foreach(c ${cases})
    string(FIND "${c}" "|" bar)
    string(SUBSTRING "${c}" 0 ${bar} scene)
    math(EXPR start "${bar} + 1")
    string(SUBSTRING "${c}" ${start} -1 want)
    run(check ${data}/${scene})
    string(REGEX REPLACE "\n$" "" err_lines "${err}")
    string(REPLACE "\n" ";" lines "${err_lines}")
    list(LENGTH lines count)
    math(EXPR last "${count} - 1")
    list(GET lines ${last} tail)
    if(NOT rc EQUAL 2 OR NOT tail MATCHES "^fftess: error: " OR count LESS 2)
      message(FATAL_ERROR "hull_bad: ${scene}: expected exit 2, diagnostics then 'fftess: error:'; got ${rc}:\n${err}")
    endif()
    list(REMOVE_AT lines ${last})
    set(found FALSE)
    foreach(l ${lines})
      if(NOT l MATCHES "^[^ :][^:]*:[0-9]+:[0-9]+: error: ")
        message(FATAL_ERROR "hull_bad: ${scene}: a diagnostic line without FILE:LINE:COL: error: '${l}'")
      endif()
      if(l MATCHES "${want}")
        set(found TRUE)
      endif()
    endforeach()
    if(NOT found)
      message(FATAL_ERROR "hull_bad: ${scene}: no line matches '${want}' in:\n${err}")
    endif()
  endforeach()
  # The evaluation shader's spacing against the scene (frustum_heightmap.tese says equal_spacing).
  run(check ${hull_examples}/frustum_heightmap_grid.toml "--set=tessellation.partitioning='fractional_odd'")
  if(NOT rc EQUAL 2 OR NOT err MATCHES "frustum_heightmap.tese:6:15: error: layout\\(equal_spacing\\) contradicts the scene's tessellation.partitioning = \"fractional_odd\"")
    message(FATAL_ERROR "hull_bad: the evaluation shader's spacing against the scene: expected exit 2 at frustum_heightmap.tese:6:15; got ${rc}:\n${err}")
  endif()
  run(check ${data}/include.toml)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "hull_bad: include.toml (the positive control): exit ${rc}: ${err}")
  endif()
  message("hull_bad: every negative fixture exits 2 with FILE:LINE:COL diagnostics; the include control runs")
else()
  message(FATAL_ERROR "hull_test.cmake: unknown CASE '${CASE}'")
endif()
