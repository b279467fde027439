# `cmake --install`: the shaderport executable, the layer libraries with their
# headers, and a CMake package (find_package(shaderport), targets shaderport::<layer>
# such as shaderport::driver); `cpack` makes a .deb that depends on the Debian
# packages the libraries link.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(shaderport_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/shaderport)
get_property(shaderport_layers GLOBAL PROPERTY SHADERPORT_LAYERS)
foreach(layer IN LISTS shaderport_layers)
  string(REGEX REPLACE "^shaderport_" "" short_name ${layer})
  set_target_properties(${layer} PROPERTIES EXPORT_NAME ${short_name})
endforeach()
set_target_properties(shaderport_glsl PROPERTIES EXPORT_NAME glsl)
set_target_properties(shaderport_warnings PROPERTIES EXPORT_NAME warnings)

install(TARGETS shaderport RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
# shaderport_warnings only carries build flags; static libraries name it in their
# link interface, so it is exported too (it adds nothing to a consumer's flags).
install(TARGETS ${shaderport_layers} shaderport_glsl shaderport_warnings
  EXPORT shaderportTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shaderport)
install(DIRECTORY src/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shaderport COMPONENT development
  FILES_MATCHING PATTERN "*.h")
install(DIRECTORY rules/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shaderport/rules
  COMPONENT development FILES_MATCHING PATTERN "*.h")
install(EXPORT shaderportTargets NAMESPACE shaderport:: DESTINATION ${shaderport_cmake_dir}
  COMPONENT development)

configure_package_config_file(cmake/shaderportConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/shaderportConfig.cmake INSTALL_DESTINATION ${shaderport_cmake_dir})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/shaderportConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/shaderportConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/shaderportConfigVersion.cmake DESTINATION ${shaderport_cmake_dir}
  COMPONENT development)
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
# The manual page and the shell completions are written by the built executable
# from its own option tables (shaderport man, shaderport completion SHELL).
set(shaderport_generated_docs ${CMAKE_CURRENT_BINARY_DIR}/generated-docs)
# After each link of the executable, so that building the target `shaderport` alone
# (the GitHub Action does) leaves everything `cmake --install` needs.
# Not VERBATIM: the generators run each command in a shell, which does the '>'.
add_custom_command(TARGET shaderport POST_BUILD
  COMMAND ${CMAKE_COMMAND} -E make_directory ${shaderport_generated_docs}
  COMMAND $<TARGET_FILE:shaderport> man > ${shaderport_generated_docs}/shaderport.1
  COMMAND $<TARGET_FILE:shaderport> completion bash > ${shaderport_generated_docs}/shaderport.bash
  COMMAND $<TARGET_FILE:shaderport> completion zsh > ${shaderport_generated_docs}/_shaderport
  COMMAND $<TARGET_FILE:shaderport> completion fish > ${shaderport_generated_docs}/shaderport.fish
  COMMENT "Writing shaderport(1) and the shell completions")
install(FILES ${shaderport_generated_docs}/shaderport.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1
  COMPONENT runtime)
install(FILES ${shaderport_generated_docs}/shaderport.bash
  DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME shaderport
  COMPONENT runtime)
install(FILES ${shaderport_generated_docs}/_shaderport
  DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/vendor-completions COMPONENT runtime)
install(FILES ${shaderport_generated_docs}/shaderport.fish
  DESTINATION ${CMAKE_INSTALL_DATADIR}/fish/vendor_completions.d COMPONENT runtime)

# cpack -G DEB: dpkg-shlibdeps turns the shared libraries the executable links
# (glslang, SPIRV-Tools, OSMesa, libpng, ...) into Depends on their Debian packages;
# the static libraries and headers need the -dev packages, listed by hand.
set(CPACK_PACKAGE_NAME shaderport)
set(CPACK_PACKAGE_VENDOR shaderport)
set(CPACK_PACKAGE_CONTACT "shaderport maintainers <shaderport@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Lint, port and validate ShaderToy and WebGL shaders for WebGL2")
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION devel)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# libOSMesa is loaded at run time (dlopen), so dpkg-shlibdeps cannot see it.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libosmesa6")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
    "glslang-dev, spirv-tools, libspirv-cross-c-shared-dev, libosmesa6-dev, libpng-dev, nlohmann-json3-dev, libtomlplusplus-dev")
include(CPack)
