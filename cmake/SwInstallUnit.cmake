# SPDX-License-Identifier: MIT
# Runs at install time (cmake/SwInstall.cmake): installs the unit's
# configuration file and its systemd unit, whose ExecStart names the
# installed seamwalk and that configuration file. It runs then, not at
# configure time, because `cmake --install --prefix` and CPack choose the
# prefix only now. Set before it: SW_UNIT_SOURCE, SW_INI_SOURCE, SW_BINDIR
# (relative to the prefix), SW_UNIT_DIR (relative), SW_UNIT_WORK (a scratch
# file in the build tree).

# The configuration lives where GNUInstallDirs puts the prefix /usr's
# (/etc): there the service and seamwalk-flash look for it. Other prefixes
# keep it inside the prefix, as GNUInstallDirs does.
if(CMAKE_INSTALL_PREFIX STREQUAL "/usr" OR CMAKE_INSTALL_PREFIX STREQUAL "/")
  set(sw_etc /etc/seamwalk)
else()
  set(sw_etc ${CMAKE_INSTALL_PREFIX}/etc/seamwalk)
endif()
file(INSTALL DESTINATION ${sw_etc} TYPE FILE FILES ${SW_INI_SOURCE})

# The unit as shipped in the source tree runs /usr/local/bin/seamwalk with
# /etc/seamwalk/seamwalk.ini; both are replaced, and a unit whose lines no
# longer say so stops the install rather than installing a wrong path.
file(READ ${SW_UNIT_SOURCE} unit)
set(exec_from "ExecStart=/usr/local/bin/seamwalk --config /etc/seamwalk/seamwalk.ini ")
set(exec_to "ExecStart=${CMAKE_INSTALL_PREFIX}/${SW_BINDIR}/seamwalk --config ${sw_etc}/seamwalk.ini ")
string(FIND "${unit}" "${exec_from}" at)
if(at LESS 0)
  message(FATAL_ERROR "${SW_UNIT_SOURCE}: no line '${exec_from}...' to point at the installed seamwalk")
endif()
string(REPLACE "${exec_from}" "${exec_to}" unit "${unit}")
get_filename_component(work_dir ${SW_UNIT_WORK} DIRECTORY)
file(MAKE_DIRECTORY ${work_dir})
file(WRITE ${SW_UNIT_WORK} "${unit}")
file(INSTALL DESTINATION ${CMAKE_INSTALL_PREFIX}/${SW_UNIT_DIR} TYPE FILE
  RENAME seamwalk.service FILES ${SW_UNIT_WORK})
