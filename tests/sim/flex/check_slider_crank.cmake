# Runs bench/flexible_slider_crank and checks its state at t = 0.1 s against
# the IVP test set's reference (benchmarks/flexible-slider-crank.md, from the
# test set's crank solution): rod angle and slider position within 1e-8,
# the elastic coordinates within 1e-6 relative, the multipliers within 1e-6
# relative (ctest -R flexible_slider_crank; PROGRAM = the bench program).
execute_process(COMMAND ${PROGRAM} OUTPUT_VARIABLE out RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "flexible_slider_crank exited with ${rc}")
endif()
message(STATUS "${out}")
set(reference
  "phi2|-0.3311734988256260|abs|1e-8"
  "x3|0.1697373328427860|abs|1e-8"
  "q1|1.893192899613509e-4|rel|1e-6"
  "q2|2.375751249879174e-5|rel|1e-6"
  "q3|-5.323896770569702e-6|rel|1e-6"
  "q4|-8.363313279112129e-6|rel|1e-6"
  "phi2_dot|60.25346755138369|rel|1e-8"
  "x3_dot|-8.753116326670527|rel|1e-8"
  "lambda1|-62.32935833287916|rel|1e-6"
  "lambda2|-163.7920993367306|rel|1e-6"
  "lambda3|25.29857947066878|rel|1e-6")
set(failed "")
foreach(row IN LISTS reference)
  string(REPLACE "|" ";" fields "${row}")
  list(GET fields 0 key)
  list(GET fields 1 want)
  list(GET fields 2 kind)
  list(GET fields 3 tol)
  string(JSON got GET "${out}" ${key})
  execute_process(COMMAND awk -v g=${got} -v w=${want} -v k=${kind} -v t=${tol}
    "BEGIN { d = g - w; if (d < 0) d = -d; if (k == \"rel\") { a = w < 0 ? -w : w; d = d / a };
             printf \"%.3e\", d; exit (d <= t) ? 0 : 1 }"
    OUTPUT_VARIABLE dev RESULT_VARIABLE bad)
  message(STATUS "${key}: ${got} vs ${want}: ${kind} deviation ${dev} (limit ${tol})")
  if(bad)
    list(APPEND failed ${key})
  endif()
endforeach()
if(failed)
  message(FATAL_ERROR "outside the tolerance: ${failed}")
endif()
