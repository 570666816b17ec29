# SPDX-License-Identifier: BSD-3-Clause
# The Mesolight VTK modules wrapped for VTK's Python (vtk_module_wrap_python), as the package
# `mesolight`: `from mesolight import vtkReliefMapper, vtkMedianCutLights`. Included by the main
# build after vtk_module_build (the ParaView plugin does not include it: ParaView wraps its modules
# its own way).
#
#   MESOLIGHT_WRAP_PYTHON        ON by default when VTK was built with Python and an interpreter
#                                imports VTK's modules (Debian: python3-vtk9)
#   MESOLIGHT_PYTHON_DESTINATION where the package goes under the prefix (VTK's own default:
#                                lib/python3/dist-packages on Debian)
#
# mesolight_wrap_python(<modules>...) wraps those of the modules that have VTK classes.

# The wrappers are built against and run by the interpreter VTK's own Python modules are for (a
# pyenv or virtualenv python3 first in PATH cannot import them). Among the candidates, the first
# that imports vtkmodules wins; Python3_EXECUTABLE given by the user is kept.
set(_mesolight_python_default OFF)
if (VTK_WRAP_PYTHON)
  if (NOT Python3_EXECUTABLE)
    foreach (_candidate IN ITEMS "${VTK_PREFIX_PATH}/bin/python3" /usr/bin/python3 python3)
      find_program(_mesolight_python NAMES "${_candidate}" NO_CACHE)
      if (_mesolight_python)
        execute_process(COMMAND "${_mesolight_python}" -c "import vtkmodules.vtkCommonCore"
          RESULT_VARIABLE _rc OUTPUT_QUIET ERROR_QUIET)
        if (_rc EQUAL 0)
          set(Python3_EXECUTABLE "${_mesolight_python}" CACHE FILEPATH
            "The Python interpreter (one that imports VTK's vtkmodules)")
          break ()
        endif ()
      endif ()
      unset(_mesolight_python)
    endforeach ()
  endif ()
  if (Python3_EXECUTABLE)
    find_package(VTK QUIET COMPONENTS Python WrappingPythonCore)
    if (TARGET VTK::Python AND TARGET VTK::WrappingPythonCore AND TARGET VTK::WrapPython)
      set(_mesolight_python_default ON)
    endif ()
  endif ()
endif ()
option(MESOLIGHT_WRAP_PYTHON
  "Wrap the Mesolight VTK modules for VTK's Python (package 'mesolight'; needs python3-vtk9)"
  ${_mesolight_python_default})
if (MESOLIGHT_WRAP_PYTHON AND NOT _mesolight_python_default)
  message(FATAL_ERROR "MESOLIGHT_WRAP_PYTHON needs VTK's Python (VTK::Python, "
    "VTK::WrappingPythonCore; Debian: python3-vtk9 and python3-dev) and an interpreter that "
    "imports vtkmodules (set Python3_EXECUTABLE)")
endif ()
if (MESOLIGHT_WRAP_PYTHON)
  vtk_module_python_default_destination(_mesolight_python_destination)
  set(MESOLIGHT_PYTHON_DESTINATION "${_mesolight_python_destination}" CACHE STRING
    "Where the 'mesolight' Python package is installed, relative to the prefix")
  message(STATUS "Mesolight: Python wrapping on (${Python3_EXECUTABLE}); package in "
    "<prefix>/${MESOLIGHT_PYTHON_DESTINATION}/mesolight")
else ()
  message(STATUS "Mesolight: Python wrapping off")
endif ()

function (mesolight_wrap_python)
  # Only modules with VTK classes have anything to wrap (Common and Evaluation hold plain C++
  # helpers); the others are marked so that the wrapped modules do not import them.
  set(_wrap)
  set(_classes)
  set(_vtk_dependencies)
  foreach (_module IN LISTS ARGN)
    _vtk_module_get_module_property(${_module} PROPERTY headers VARIABLE _headers)
    set(_has_classes OFF)
    foreach (_header IN LISTS _headers)
      file(READ "${_header}" _text)
      if (_text MATCHES "vtkTypeMacro\\(")
        set(_has_classes ON)
        get_filename_component(_class "${_header}" NAME_WE)
        list(APPEND _classes "${_class}")
      endif ()
    endforeach ()
    if (NOT _has_classes)
      _vtk_module_set_module_property(${_module} PROPERTY exclude_wrap VALUE 1)
      continue ()
    endif ()
    list(APPEND _wrap ${_module})
    # The VTK modules the package imports before its own (see python/__init__.py.in).
    _vtk_module_get_module_property(${_module} PROPERTY depends VARIABLE _depends)
    _vtk_module_get_module_property(${_module} PROPERTY private_depends VARIABLE _private)
    foreach (_depend IN LISTS _depends _private)
      # (Two ifs: the arguments of one are expanded before its MATCHES sets CMAKE_MATCH_1.)
      if (_depend MATCHES "^VTK::(.*)$")
        set(_name "vtk${CMAKE_MATCH_1}")
        if (TARGET "VTK::${_name}Python")
          list(APPEND _vtk_dependencies "${_name}")
        endif ()
      endif ()
    endforeach ()
  endforeach ()
  list(REMOVE_DUPLICATES _vtk_dependencies)
  list(SORT _vtk_dependencies)

  # The extension modules find the Mesolight libraries from <destination>/mesolight.
  file(RELATIVE_PATH _to_libraries
    "/prefix/${MESOLIGHT_PYTHON_DESTINATION}/mesolight" "/prefix/${CMAKE_INSTALL_LIBDIR}")
  set(CMAKE_INSTALL_RPATH "$ORIGIN/${_to_libraries}")
  vtk_module_wrap_python(
    MODULES            ${_wrap}
    WRAPPED_MODULES    _wrapped
    PYTHON_PACKAGE     mesolight
    MODULE_DESTINATION "${MESOLIGHT_PYTHON_DESTINATION}"
    INSTALL_HEADERS    OFF
    BUILD_STATIC       OFF)

  set(_library_names)
  foreach (_module IN LISTS _wrapped)
    _vtk_module_get_module_property(${_module} PROPERTY library_name VARIABLE _library_name)
    list(APPEND _library_names "${_library_name}")
  endforeach ()
  set(_vtk_imports)
  foreach (_dependency IN LISTS _vtk_dependencies)
    string(APPEND _vtk_imports "import vtkmodules.${_dependency}\n")
  endforeach ()
  set(_mesolight_imports)
  foreach (_library_name IN LISTS _library_names)
    string(APPEND _mesolight_imports "from .${_library_name} import *\n")
  endforeach ()
  set(MESOLIGHT_PYTHON_VTK_IMPORTS "${_vtk_imports}")
  set(MESOLIGHT_PYTHON_IMPORTS "${_mesolight_imports}")
  set(MESOLIGHT_VERSION "${PROJECT_VERSION}")
  set(_package "${CMAKE_BINARY_DIR}/${MESOLIGHT_PYTHON_DESTINATION}/mesolight")
  configure_file("${PROJECT_SOURCE_DIR}/python/__init__.py.in" "${_package}/__init__.py" @ONLY)
  install(FILES "${_package}/__init__.py"
    DESTINATION "${MESOLIGHT_PYTHON_DESTINATION}/mesolight")
  set(MESOLIGHT_PYTHON_PACKAGE_DIR "${CMAKE_BINARY_DIR}/${MESOLIGHT_PYTHON_DESTINATION}"
    PARENT_SCOPE)
  set(MESOLIGHT_PYTHON_MODULES "${_library_names}" PARENT_SCOPE)
  # The public VTK classes (one per installed header with a vtkTypeMacro), which the package
  # test expects in the package.
  list(SORT _classes)
  set(MESOLIGHT_PYTHON_CLASSES "${_classes}" PARENT_SCOPE)
endfunction ()
