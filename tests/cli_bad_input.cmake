# Bad input through the real executable: each case must fail (nonzero exit) with a message
# that names the option and the value. Each case: "arguments|regex". Run with -DEXE=... -DSRC=... -DMPIEXEC=...
set(cases
  "-beam_length -1|-beam_length -1\\.? is not allowed"
  "-beam_nodes 3|-beam_nodes 3\\.? is not allowed: at least 5"
  "-beam_thickness 0|-beam_thickness 0\\.? is not allowed"
  "-ball_mass -0.1|-ball_mass -0.1 is not allowed"
  "-ball_speed 0|-ball_speed 0\\.? is not allowed"
  "-ball_k -5|-ball_k -5\\.? is not allowed"
  "-ball_law rubber|rubber"
  "-beam_left glued|glued"
  "-impact_x 1.5|-impact_x 1.5 is not allowed"
  "-beam_left clamped -impact_x 0|-impact_x 0\\.? is not allowed: that point is held fixed"
  "-beam_clamp 0,0.3 -impact_x 0.2|-impact_x 0.2 is not allowed: that point is held fixed"
  "-beam_clamp 0.5,0.2|-beam_clamp 0.5,0.2\\.? is not allowed"
  "-beam_density 3000 -beam_EI 40 -beam_mu 0.5|contradicting beam parameter sets"
  "-beam_mass 0.3 -beam_youngs_over_density 1e7 -beam_density 2700|contradicting beam parameter sets"
  "-beam_EI 40|-beam_EI and -beam_mu go together"
  "-ball_law linear -ball_n 2|-ball_n is a hysteresis parameter"
  "-ball_law hysteresis -ball_n 0.5|-ball_n 0.5 is not allowed"
  "-beam_lenght 1.0|option\\(s\\) set but not used.*-beam_lenght"
  "-ts_type rk -ts_rk_type 2a -ts_adapt_type none|unstable for an undamped oscillation at any step"
  "-ts_type rk -ts_rk_type 4 -ts_adapt_type none -ts_dt 1e-3|-ts_dt 0.001 is above the stability limit dt_max"
  "-ts_type euler|-ts_type euler cannot roll back a step"
  "-ts_type ssp|-ts_type ssp cannot roll back a step"
  "-task juggle|juggle"
)
foreach(c IN LISTS cases)
  string(FIND "${c}" "|" bar)
  string(SUBSTRING "${c}" 0 ${bar} args)
  math(EXPR bar "${bar} + 1")
  string(SUBSTRING "${c}" ${bar} -1 regex)
  separate_arguments(parts UNIX_COMMAND "${args}")
  execute_process(COMMAND ${EXE} ${parts} -output none
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
  if(rc EQUAL 0)
    message(FATAL_ERROR "accepted bad input: ${parts}\n${out}")
  endif()
  if(NOT "${out}${err}" MATCHES "${regex}")
    message(FATAL_ERROR "bad input ${parts}: message does not match '${regex}':\n${out}${err}")
  endif()
  if("${out}${err}" MATCHES "nan|NaN")
    message(FATAL_ERROR "bad input ${parts}: output mentions NaN:\n${out}${err}")
  endif()
  message(STATUS "ok: ${parts} -> ${regex}")
endforeach()
