# SPDX-License-Identifier: MIT
# What `cmake --install` puts where, in two components (docs/building.md,
# "Installing and packaging"):
#   runtime  seamwalk, seamwalk-flash, the systemd unit, the udev rule, the
#            sysusers.d file, /etc/seamwalk/seamwalk.ini, their man pages
#   host     seamwalk-pack and its man page
# The programs' own install() lines are beside them (firmware/, assets/).
# systemd, udev and sysusers read lib/ under /usr and /usr/local alike, not
# the multiarch libdir, so these directories are relative to the prefix.
set(SW_SYSTEMD_UNIT_DIR lib/systemd/system CACHE STRING "systemd system units, under the prefix")
set(SW_UDEV_RULES_DIR lib/udev/rules.d CACHE STRING "udev rules, under the prefix")
set(SW_SYSUSERS_DIR lib/sysusers.d CACHE STRING "sysusers.d files, under the prefix")

set(sw_man ${PROJECT_SOURCE_DIR}/docs/man)
set(sw_fw ${PROJECT_SOURCE_DIR}/firmware/dist)

install(FILES ${sw_fw}/70-seamwalk.rules DESTINATION ${SW_UDEV_RULES_DIR} COMPONENT runtime)
install(FILES ${sw_fw}/seamwalk.sysusers DESTINATION ${SW_SYSUSERS_DIR}
  RENAME seamwalk.conf COMPONENT runtime)
install(FILES ${sw_man}/seamwalk.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT runtime)
install(FILES ${sw_man}/seamwalk-flash.8 DESTINATION ${CMAKE_INSTALL_MANDIR}/man8 COMPONENT runtime)
install(FILES ${sw_man}/seamwalk.ini.5 DESTINATION ${CMAKE_INSTALL_MANDIR}/man5 COMPONENT runtime)
# Debian wants each package's licence as share/doc/PACKAGE/copyright.
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/seamwalk
  RENAME copyright COMPONENT runtime)
# The unit and the config file need the prefix chosen at install time.
install(CODE "
  set(SW_UNIT_SOURCE \"${sw_fw}/seamwalk.service\")
  set(SW_INI_SOURCE \"${sw_fw}/seamwalk.ini\")
  set(SW_BINDIR \"${CMAKE_INSTALL_BINDIR}\")
  set(SW_UNIT_DIR \"${SW_SYSTEMD_UNIT_DIR}\")
  set(SW_UNIT_WORK \"${PROJECT_BINARY_DIR}/install/seamwalk.service\")
  include(\"${PROJECT_SOURCE_DIR}/cmake/SwInstallUnit.cmake\")" COMPONENT runtime)

if(SW_BUILD_PACK_TOOL)
  install(FILES ${sw_man}/seamwalk-pack.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT host)
  install(FILES ${PROJECT_SOURCE_DIR}/LICENSE
    DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/seamwalk-pack RENAME copyright COMPONENT host)
endif()

include(SwPackage)
