# Finds PCL 1.13's headers and the libraries the descriptor peers need, without PCLConfig.cmake
# (Debian's pulls in VTK, whose config fails for want of MPI targets). Defines the imported target
# ShapeCorr_PCL when everything is there.
if(NOT TARGET ShapeCorr_PCL)
  find_path(SHAPECORR_PCL_INCLUDE_DIR pcl/features/shot.h PATH_SUFFIXES pcl-1.13)
  find_library(SHAPECORR_PCL_FEATURES pcl_features)
  find_library(SHAPECORR_PCL_SEARCH pcl_search)
  find_library(SHAPECORR_PCL_KDTREE pcl_kdtree)
  find_library(SHAPECORR_PCL_COMMON pcl_common)
  find_library(SHAPECORR_FLANN flann_cpp)
  if(SHAPECORR_PCL_INCLUDE_DIR AND SHAPECORR_PCL_FEATURES AND SHAPECORR_PCL_SEARCH AND SHAPECORR_PCL_KDTREE
     AND SHAPECORR_PCL_COMMON AND SHAPECORR_FLANN)
    add_library(ShapeCorr_PCL INTERFACE IMPORTED)
    target_include_directories(ShapeCorr_PCL INTERFACE ${SHAPECORR_PCL_INCLUDE_DIR})
    target_link_libraries(ShapeCorr_PCL INTERFACE ${SHAPECORR_PCL_FEATURES} ${SHAPECORR_PCL_SEARCH} ${SHAPECORR_PCL_KDTREE}
                          ${SHAPECORR_PCL_COMMON} ${SHAPECORR_FLANN})
    target_compile_definitions(ShapeCorr_PCL INTERFACE SHAPECORR_WITH_PCL)
    message(STATUS "ShapeCorr: PCL found (${SHAPECORR_PCL_INCLUDE_DIR})")
  endif()
endif()
