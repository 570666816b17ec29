# SPDX-License-Identifier: BSD-3-Clause
# mesolight_encode_shaders(<sources var> <headers var> <file.glsl>...)
# Each GLSL file becomes a C string (vtk_encode_string), so shaders are edited as .glsl files but
# need no files at run time; the generated sources and headers are returned in the two variables.
function (mesolight_encode_shaders sources_var headers_var)
  set(sources)
  set(headers)
  foreach (shader_file IN LISTS ARGN)
    vtk_encode_string(
      INPUT         "${shader_file}"
      HEADER_OUTPUT header
      SOURCE_OUTPUT source)
    list(APPEND sources "${source}")
    list(APPEND headers "${header}")
  endforeach ()
  set("${sources_var}" "${sources}" PARENT_SCOPE)
  set("${headers_var}" "${headers}" PARENT_SCOPE)
endfunction ()
