# Options HSLAM_SANITIZE (ASan + UBSan, any compiler) and HSLAM_FUZZ (clang:
# every target instrumented for libFuzzer coverage; tests/fuzz adds the
# fuzz_<target> binaries). Used by scripts/run-tests.sh in a separate build
# folder (build-sanitize); see README "Tests".
if(HSLAM_SANITIZE OR HSLAM_FUZZ)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
if(HSLAM_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "HSLAM_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
