# SPDX-License-Identifier: MIT
# Compiler options applied per target (never through CMAKE_CXX_FLAGS), see STYLE.md §9.

function(sparsedyn_target_options target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
                                           -Wnon-virtual-dtor -ffp-contract=off
                                           # Designated initialisers (STYLE.md §2) omit fields on purpose.
                                           -Wno-missing-field-initializers)
  if(SPARSEDYN_WARNINGS_AS_ERRORS)
    # GCC 12 at -O3 reports false -Wrestrict positives inside libstdc++ std::string (GCC bug
    # 105329); keep them visible but not fatal. The flag is GCC's only: clang refuses it.
    target_compile_options(${target} PRIVATE -Werror
                                             $<$<CXX_COMPILER_ID:GNU>:-Wno-error=restrict>)
  endif()
  if(SPARSEDYN_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined
                                             -fno-sanitize-recover=undefined
                                             -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
  if(SPARSEDYN_FUZZ AND target MATCHES "^sparsedyn(_scenes|_fuzz_entries)?$")
    # libFuzzer's coverage feedback (clang only) in the code the fuzz targets of tests/fuzz/ run,
    # not in the tests (it would only slow their build); the fuzz executables add
    # -fsanitize=fuzzer.
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()
