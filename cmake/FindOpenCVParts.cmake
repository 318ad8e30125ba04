# Debian's CMake config for OpenCV ships only with libopencv-dev, which pulls in
# ~150 packages (Qt, VTK, ffmpeg). dvpr needs core, imgproc and imgcodecs, whose
# -dev packages ship headers and libraries but no config, so locate them here.
find_path(OpenCV_INCLUDE_DIR opencv2/core.hpp PATH_SUFFIXES opencv4 REQUIRED)
add_library(dvpr_opencv INTERFACE)
target_include_directories(dvpr_opencv SYSTEM INTERFACE ${OpenCV_INCLUDE_DIR})
foreach(part core imgproc imgcodecs)
  find_library(OpenCV_${part}_LIBRARY opencv_${part} REQUIRED)
  target_link_libraries(dvpr_opencv INTERFACE ${OpenCV_${part}_LIBRARY})
endforeach()
