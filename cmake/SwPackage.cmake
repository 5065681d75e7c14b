# SPDX-License-Identifier: MIT
# CPack: one Debian package per install component (cmake/SwInstall.cmake),
#   seamwalk       the runtime component, for the units
#   seamwalk-pack  the host component, for whoever builds packs
# made by `bash tests/run-package.sh` into build/packages (by hand: cpack
# --config BUILD/CPackConfig.cmake -B DIR). Their Depends come from
# dpkg-shlibdeps (dpkg-dev) on the programs as built, so they name exactly
# the libraries linked.
set(SW_PACKAGE_MAINTAINER "seamwalk maintainers <maintainers@seamwalk.invalid>"
  CACHE STRING "the Maintainer field of the .deb packages")

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME seamwalk)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "the seamwalk authors")
set(CPACK_PACKAGE_CONTACT ${SW_PACKAGE_MAINTAINER})
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_STRIP_FILES ON)
# /etc/seamwalk is outside the prefix /usr: with DESTDIR the install keeps
# it under the package's root instead of writing the build machine's /etc.
set(CPACK_SET_DESTDIR ON)
set(CPACK_INSTALL_PREFIX /usr)   # the prefix under DESTDIR
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime)
if(SW_BUILD_PACK_TOOL)
  list(APPEND CPACK_COMPONENTS_ALL host)
endif()
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)   # NAME_VERSION_ARCH.deb
# CPack names the build machine's architecture; a cross build's packages
# hold the target's programs (cmake/aarch64-linux-gnu.cmake: arm64).
if(CMAKE_CROSSCOMPILING)
  execute_process(COMMAND dpkg-architecture -t ${CMAKE_LIBRARY_ARCHITECTURE} -qDEB_HOST_ARCH
    OUTPUT_VARIABLE CPACK_DEBIAN_PACKAGE_ARCHITECTURE OUTPUT_STRIP_TRAILING_WHITESPACE
    ERROR_QUIET COMMAND_ERROR_IS_FATAL ANY)
endif()
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)

set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME seamwalk)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SECTION misc)
set(CPACK_COMPONENT_RUNTIME_DESCRIPTION "walk through large CAD models on a kiosk display
seamwalk walks a signed pack of trimmed NURBS surfaces on a display unit
(KMS, X11, Wayland or headless, OpenGL ES 2 on EGL), tessellating on the
fly within a screen-space error bound, driven by gamepads, GPIO buttons or
a keyboard, as a systemd service. seamwalk-flash installs packs into the
unit's two-slot pack store.")
# postinst runs systemd-sysusers, which Debian ships in systemd or alone.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS "systemd | systemd-standalone-sysusers")
# dpkg keeps a unit's own changes to a conffile over an upgrade.
file(WRITE ${PROJECT_BINARY_DIR}/deb/conffiles "/etc/seamwalk/seamwalk.ini\n")
set(CPACK_DEBIAN_RUNTIME_PACKAGE_CONTROL_EXTRA ${PROJECT_BINARY_DIR}/deb/conffiles
  ${PROJECT_SOURCE_DIR}/cmake/deb/postinst ${PROJECT_SOURCE_DIR}/cmake/deb/postrm)

set(CPACK_DEBIAN_HOST_PACKAGE_NAME seamwalk-pack)
set(CPACK_DEBIAN_HOST_PACKAGE_SECTION graphics)
set(CPACK_COMPONENT_HOST_DESCRIPTION "build, sign and inspect seamwalk packs
seamwalk-pack turns CAD files (IGES, STEP, Newell listings, Bezier patch
text, showroom scenes) into validated packs for seamwalk, signs them with
ed25519 keys and shows what is inside.")

include(CPack)
