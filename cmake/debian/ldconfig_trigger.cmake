# SPDX-License-Identifier: BSD-3-Clause
# CPACK_POST_BUILD_SCRIPTS (cmake/package.cmake): CPack gives a package with a library under /usr/lib a postinst
# and a postrm that call ldconfig; Debian runs ldconfig once per dpkg run through libc-bin's trigger instead
# (lintian: maintscript-calls-ldconfig). The shared library's package is rebuilt with DEBIAN/triggers in their place.
foreach(file IN LISTS CPACK_PACKAGE_FILES)
  if(file MATCHES "/librestitution[0-9.]+_[^/]*\\.deb$")
    set(tree ${file}.tree)
    file(REMOVE_RECURSE ${tree})
    execute_process(COMMAND dpkg-deb -R ${file} ${tree} COMMAND_ERROR_IS_FATAL ANY)
    file(REMOVE ${tree}/DEBIAN/postinst ${tree}/DEBIAN/postrm)
    file(WRITE ${tree}/DEBIAN/triggers "activate-noawait ldconfig\n")
    execute_process(COMMAND dpkg-deb --root-owner-group -b ${tree} ${file} OUTPUT_QUIET COMMAND_ERROR_IS_FATAL ANY)
    file(REMOVE_RECURSE ${tree})
  endif()
endforeach()
