# ml_draco: Debian's libdraco (libdraco-dev) as the Draco codec alone.
#
# Its library also carries a glTF transcoder with its own copies of tinygltf and stb_image, built
# with another configuration and class layout. The shared library exports them, so that its
# tinygltf stands in for libtinygltf's at run time (a crash in ~TinyGLTF); from the archive, the
# linker takes them wherever it meets them before libtinygltf or libstb. So the archive is copied
# without the members that define them; if the codec ever needed one, the link would fail loudly.
find_package(draco REQUIRED)
set(ML_DRACO_CODEC ${CMAKE_BINARY_DIR}/draco/libml_draco_codec.a)
get_target_property(ML_DRACO_ARCHIVE draco::draco_static IMPORTED_LOCATION_NONE)
if(NOT ML_DRACO_ARCHIVE)
  get_target_property(ML_DRACO_ARCHIVE draco::draco_static LOCATION)
endif()
add_custom_command(
  OUTPUT ${ML_DRACO_CODEC}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/draco
  COMMAND ${CMAKE_COMMAND} -E copy ${ML_DRACO_ARCHIVE} ${ML_DRACO_CODEC}
  COMMAND ${CMAKE_AR} d ${ML_DRACO_CODEC} tiny_gltf_utils.cc.o gltf_decoder.cc.o mesh_io.cc.o scene_io.cc.o
  COMMAND ${CMAKE_RANLIB} ${ML_DRACO_CODEC}
  DEPENDS ${ML_DRACO_ARCHIVE}
  COMMENT "Taking libdraco's codec without its bundled tinygltf and stb_image"
  VERBATIM)
add_custom_target(ml_draco_codec DEPENDS ${ML_DRACO_CODEC})
add_library(ml_draco STATIC IMPORTED GLOBAL)
set_target_properties(ml_draco PROPERTIES IMPORTED_LOCATION ${ML_DRACO_CODEC})
add_dependencies(ml_draco ml_draco_codec)
