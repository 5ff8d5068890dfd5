# Each lab owns NN-name/lab.cmake with its add_lab() call; listed here in course order.
foreach(lab 01-affine 02-lighting 03-transforms 04-textures 05-stencil 06-bezier 07-raytrace 08-radiosity)
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${lab}/lab.cmake)
    include(${lab}/lab.cmake)
  endif()
endforeach()
