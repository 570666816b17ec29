# SPDX-License-Identifier: BSD-3-Clause
# Where Mesolight's VTK modules are: the one list of the directories that hold them. The main
# build and the ParaView plugin both find the vtk.module files below these directories
# (vtk_module_find_modules), so a new module is found where it is put, with no list to keep.
#
# mesolight_find_modules(<files variable> <names variable> <source dir> [WITH_EVALUATION])
#   The vtk.module files and the module names (Mesolight::...) of the library modules; with
#   WITH_EVALUATION also Mesolight::Evaluation (the references the tests and benchmarks measure
#   against; the plugin does not ship it).
function(mesolight_find_modules files_variable names_variable source_dir)
  cmake_parse_arguments(PARSE_ARGV 3 _mesolight "WITH_EVALUATION" "" "")
  set(_directories
    "${source_dir}/common"
    "${source_dir}/filters"
    "${source_dir}/reliefcore"
    "${source_dir}/vtkRelief"
    "${source_dir}/vtkScene"
    "${source_dir}/vtkRayTracing"
    "${source_dir}/vtkVLF")
  if (_mesolight_WITH_EVALUATION)
    list(APPEND _directories "${source_dir}/evaluation")
  endif ()
  vtk_module_find_modules(_files ${_directories})
  list(SORT _files)
  set(_names)
  foreach (_file IN LISTS _files)
    file(STRINGS "${_file}" _lines)
    list(FIND _lines "NAME" _index)
    math(EXPR _index "${_index} + 1")
    list(GET _lines ${_index} _name)
    string(STRIP "${_name}" _name)
    list(APPEND _names "${_name}")
  endforeach ()
  set(${files_variable} "${_files}" PARENT_SCOPE)
  set(${names_variable} "${_names}" PARENT_SCOPE)
endfunction()
