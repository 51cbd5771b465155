# Third-party packages, all from Debian. Their headers stay inside .cpp files.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(OpenMesh REQUIRED)
# zlib linked from its static archive (Debian builds it position-independent): as a shared library
# it cost every process 0.06 ms of loading at start (docs/benchmarks.md, "Start-up"). Not GMP:
# Debian's libgmp.a has objects that cannot go into a shared library (libuvtk, the Python module).
set(ZLIB_USE_STATIC_LIBS ON)
find_package(CGAL REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(OpenImageIO REQUIRED)
find_package(OpenSSL REQUIRED)  # SHA-256 of the inputs a report measured
find_package(ZLIB REQUIRED)  # CRC-32, to check PNG files before libpng reads them
find_package(dragonbox REQUIRED)  # Dragonbox (header only): the digits of the numbers the mesh writers write
# SLEEF: the vectorised atan2 of --math fast (Debian's libsleef-dev ships a pkg-config file).
find_package(PkgConfig REQUIRED)
pkg_check_modules(SLEEF REQUIRED IMPORTED_TARGET sleef)

# Debian's OpenImageIO package lists /usr/include/opencv4 as an include directory even when
# OpenCV is not installed, and CMake's generate step then fails. Keep only directories that exist.
foreach(prop INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
  get_target_property(dirs OpenImageIO::OpenImageIO ${prop})
  if(dirs)
    set(existing "")
    foreach(dir IN LISTS dirs)
      if(EXISTS "${dir}")
        list(APPEND existing "${dir}")
      endif()
    endforeach()
    set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${prop} "${existing}")
  endif()
endforeach()

if(UVTK_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
# Google Benchmark times `uvtk bench` as well as the programs under bench/.
find_package(benchmark REQUIRED)
