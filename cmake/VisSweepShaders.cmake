# vissweep_compile_shaders(<out-var> SHADERS <file.comp>... INCLUDE_DIRS <dir>...)
# Compiles GLSL compute shaders to SPIR-V at build time with glslangValidator and
# writes each as a C header (`--vn vs_spirv_<name>`), so the library embeds its
# shaders and looks nothing up at run time. <out-var> receives the generated headers.
function(vissweep_compile_shaders out_var)
  cmake_parse_arguments(ARG "" "" "SHADERS;INCLUDE_DIRS;DEPENDS" ${ARGN})
  set(generated)
  set(include_flags)
  foreach (dir IN LISTS ARG_INCLUDE_DIRS)
    list(APPEND include_flags "-I${dir}")
  endforeach ()
  set(out_dir "${CMAKE_CURRENT_BINARY_DIR}/spirv")
  file(MAKE_DIRECTORY "${out_dir}")
  foreach (shader IN LISTS ARG_SHADERS)
    get_filename_component(name "${shader}" NAME_WE)
    get_filename_component(abs "${shader}" ABSOLUTE)
    set(out "${out_dir}/vs_spirv_${name}.h")
    add_custom_command(
      OUTPUT "${out}"
      COMMAND "${GLSLANG_VALIDATOR}" --quiet --target-env vulkan1.1 ${include_flags}
              --vn "vs_spirv_${name}" -o "${out}" "${abs}"
      DEPENDS "${abs}" ${ARG_DEPENDS}
      COMMENT "Compiling compute shader ${name} to SPIR-V"
      VERBATIM)
    list(APPEND generated "${out}")
  endforeach ()
  set(${out_var} ${generated} PARENT_SCOPE)
endfunction ()
