# Runs `two_blocks --json ARGS`, then compares its numbers with BASELINE.
# -DEXE=... -DCOMPARE=... -DBASELINE=... -DOUT=... -DARGS="a;b;c" [-DBLESS=1]
if(NOT EXISTS "${EXE}")
  message(FATAL_ERROR "${EXE} does not exist: build it with `cargo build --release --examples` "
    "(same CARGO_TARGET_DIR as when c_tests was configured) or configure with -DTFEM_TWO_BLOCKS_EXE=<path>")
endif()
execute_process(COMMAND "${EXE}" ${ARGS} --json --out "${OUT}.d"
  OUTPUT_FILE "${OUT}" RESULT_VARIABLE run_rc)
if(NOT run_rc EQUAL 0)
  message(FATAL_ERROR "${EXE} ${ARGS} --json failed (${run_rc})")
endif()
if(BLESS)
  set(flag --bless)
endif()
execute_process(COMMAND "${COMPARE}" ${flag} "${BASELINE}" "${OUT}" RESULT_VARIABLE cmp_rc)
if(NOT cmp_rc EQUAL 0)
  message(FATAL_ERROR "regression: numbers moved beyond their tolerances (table above); "
    "if the change is intended, rerun with -DTFEM_BLESS_BASELINES=ON")
endif()
