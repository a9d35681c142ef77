#[==[
Debian 12's paraview-dev ships no VTK wrapping hierarchy files: its module properties name
`.../vtk/hierarchy/ParaView/<library>-hierarchy.txt` for every wrapped VTK and ParaView module,
but none of those files is in any package, and `vtk_module_build` with wrapping (the client-server
wrapping every ParaView plugin needs) stops with "missing and no known rule to make it".

A hierarchy file lists the classes of one module with their superclasses, as parsed from the
module's installed headers. The `paraview` package ships the tool that writes them,
vtkWrapHierarchy-pv5.11, and the module properties list every module's headers and dependencies.
So this function writes the hierarchy files of a module and of all the modules it depends on
(publicly, recursively: what vtkWrapHierarchy reads), in dependency order, at configure time,
into ${CMAKE_BINARY_DIR}/vtk-hierarchy/, exactly as VTK's own `_vtk_module_write_wrap_hierarchy`
does (one `header;library` line per header, the dependencies' hierarchy files as arguments), and
points each imported target's `INTERFACE_vtk_module_hierarchy` property at the file it wrote.
Files that exist already (a ParaView that ships them) are used as they are.

  vissweep_paraview_hierarchy(<module>...)
#]==]
function (_vissweep_paraview_hierarchy_one module)
  get_property(done GLOBAL PROPERTY "_vissweep_pv_hierarchy_done_${module}" SET)
  if (done OR NOT TARGET "${module}")
    return ()
  endif ()
  set_property(GLOBAL PROPERTY "_vissweep_pv_hierarchy_done_${module}" 1)
  get_property(hierarchy TARGET "${module}" PROPERTY INTERFACE_vtk_module_hierarchy)
  get_property(imported TARGET "${module}" PROPERTY IMPORTED)
  if (NOT hierarchy OR NOT imported OR EXISTS "${hierarchy}")
    return ()
  endif ()

  get_property(depends TARGET "${module}" PROPERTY INTERFACE_vtk_module_depends)
  set(depend_files)
  foreach (depend IN LISTS depends)
    _vissweep_paraview_hierarchy_one("${depend}")
    if (TARGET "${depend}")
      get_property(depend_file TARGET "${depend}" PROPERTY INTERFACE_vtk_module_hierarchy)
      if (depend_file)
        list(APPEND depend_files "${depend_file}")
      endif ()
    endif ()
  endforeach ()

  get_property(library TARGET "${module}" PROPERTY INTERFACE_vtk_module_library_name)
  get_filename_component(name "${hierarchy}" NAME)
  if (VISSWEEP_PV_HIERARCHY_DIR AND EXISTS "${VISSWEEP_PV_HIERARCHY_DIR}/${name}")
    set_property(TARGET "${module}" PROPERTY INTERFACE_vtk_module_hierarchy
      "${VISSWEEP_PV_HIERARCHY_DIR}/${name}")
    return ()
  endif ()
  get_property(headers TARGET "${module}" PROPERTY INTERFACE_vtk_module_headers)
  set(dir "${CMAKE_BINARY_DIR}/vtk-hierarchy")
  set(out "${dir}/${library}-hierarchy.txt")
  if (NOT EXISTS "${out}")
    set(data "")
    foreach (header IN LISTS headers)
      string(APPEND data "${header};${library}\n")
    endforeach ()
    file(WRITE "${dir}/${library}-hierarchy.data" "${data}")
    set(args "")
    foreach (include IN LISTS _vissweep_pv_include_dirs)
      string(APPEND args "-I\"${include}\"\n")
    endforeach ()
    file(WRITE "${dir}/${library}-hierarchy.args" "${args}")
    # After the data file (the first file argument is the header list), as VTK passes them.
    set(depends_args "")
    foreach (depend_file IN LISTS depend_files)
      string(APPEND depends_args "\"${depend_file}\"\n")
    endforeach ()
    file(WRITE "${dir}/${library}-hierarchy.depends.args" "${depends_args}")
    execute_process(
      COMMAND "${_vissweep_pv_wrap_hierarchy}" "@${dir}/${library}-hierarchy.args"
              -o "${out}.tmp" "${dir}/${library}-hierarchy.data"
              "@${dir}/${library}-hierarchy.depends.args"
      RESULT_VARIABLE result
      ERROR_VARIABLE  error)
    if (NOT result EQUAL 0)
      message(FATAL_ERROR "vtkWrapHierarchy failed for ${module} (${library}): ${error}")
    endif ()
    file(RENAME "${out}.tmp" "${out}")
  endif ()
  set_property(TARGET "${module}" PROPERTY INTERFACE_vtk_module_hierarchy "${out}")
endfunction ()

function (vissweep_paraview_hierarchy)
  set(tool "")
  if (TARGET VTK::WrapHierarchy)
    get_property(tool TARGET VTK::WrapHierarchy PROPERTY LOCATION)
  endif ()
  if (NOT tool OR NOT EXISTS "${tool}")
    # ParaView's version, or (VisSweep's own build against ParaView's VTK, no ParaView package) 5.11's.
    find_program(tool NAMES vtkWrapHierarchy-pv${ParaView_VERSION_MAJOR}.${ParaView_VERSION_MINOR}
      vtkWrapHierarchy-pv5.11)
  endif ()
  if (NOT tool)
    message(FATAL_ERROR "ParaView's vtkWrapHierarchy was not found (Debian: the paraview package)")
  endif ()
  set(_vissweep_pv_wrap_hierarchy "${tool}")
  get_property(_vissweep_pv_include_dirs TARGET VTK::CommonCore PROPERTY INTERFACE_INCLUDE_DIRECTORIES)
  foreach (module IN LISTS ARGN)
    _vissweep_paraview_hierarchy_one("${module}")
  endforeach ()
endfunction ()
