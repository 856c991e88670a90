# The compiled libraries hsx's public headers need (GMP's C and C++ interfaces, MPFR), as imported targets.
# Included by hsx's own build and by the installed hsxConfig.cmake, so that a consumer finds the same libraries.
if(NOT TARGET hsx::gmp)
  find_path(HSX_GMP_INCLUDE_DIR gmpxx.h REQUIRED)
  find_path(HSX_MPFR_INCLUDE_DIR mpfr.h REQUIRED)
  find_library(HSX_GMP_LIBRARY gmp REQUIRED)
  find_library(HSX_GMPXX_LIBRARY gmpxx REQUIRED)
  find_library(HSX_MPFR_LIBRARY mpfr REQUIRED)
  add_library(hsx::gmp UNKNOWN IMPORTED)
  set_target_properties(hsx::gmp PROPERTIES IMPORTED_LOCATION "${HSX_GMP_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${HSX_GMP_INCLUDE_DIR}")
  add_library(hsx::gmpxx UNKNOWN IMPORTED)
  set_target_properties(hsx::gmpxx PROPERTIES IMPORTED_LOCATION "${HSX_GMPXX_LIBRARY}"
                        INTERFACE_LINK_LIBRARIES hsx::gmp)
  add_library(hsx::mpfr UNKNOWN IMPORTED)
  set_target_properties(hsx::mpfr PROPERTIES IMPORTED_LOCATION "${HSX_MPFR_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${HSX_MPFR_INCLUDE_DIR}" INTERFACE_LINK_LIBRARIES hsx::gmp)
endif()
