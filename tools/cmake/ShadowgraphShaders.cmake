# SPDX-License-Identifier: MIT
# Compiles GLSL stages to SPIR-V with glslangValidator and emits each as a C++ header
# (`<prefix>/<file>.spv.h`, an array named after the file, e.g. scene_vert), so binaries embed
# their shaders and a missing shader is a compile error, not a run-time file lookup.
#
# shadowgraph_add_shaders(<target> <source dir> <include prefix>) makes INTERFACE library
# <target> for every .vert/.frag/.geom/.comp in <source dir> and the variants each declares;
# its .glsl files and the engine's (SHADOWGRAPH_SHADER_DIR: shaders/ in the tree,
# share/shadowgraph/shaders installed) are on the include path and dependencies, so passes
# written elsewhere include the engine's interfaces by name ("bindings.glsl").
function(shadowgraph_add_shaders target source_dir prefix)
  file(GLOB sources CONFIGURE_DEPENDS
       ${source_dir}/*.vert ${source_dir}/*.frag ${source_dir}/*.geom ${source_dir}/*.comp)
  file(GLOB includes CONFIGURE_DEPENDS ${source_dir}/*.glsl ${SHADOWGRAPH_SHADER_DIR}/*.glsl)
  set(include_root ${CMAKE_CURRENT_BINARY_DIR}/${target}_include)
  set(spirv_dir ${include_root}/${prefix})
  file(MAKE_DIRECTORY ${spirv_dir})
  set(headers)
  foreach(source ${sources})
    get_filename_component(file_name ${source} NAME)
    get_filename_component(stem ${source} NAME_WE)
    get_filename_component(stage ${source} LAST_EXT)
    # The source itself, then each variant it declares on a line of its own as
    # `// variant <suffix> <DEFINE>...`: the same source compiled with each DEFINE (NAME or
    # NAME=number) set, emitted as <stem>_<suffix><stage>.spv.h, so a pass's variants live in the
    # one file.
    set(builds "${file_name}")
    file(STRINGS ${source} variant_lines REGEX "^// variant [a-z0-9_]+( [A-Z_]+(=[0-9]+)?)+$")
    # A variant declared later must reach the build: editing a shader configures again.
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${source})
    foreach(line ${variant_lines})
      string(REGEX REPLACE "^// variant ([a-z0-9_]+) (.+)$" "\\1" suffix "${line}")
      string(REGEX REPLACE "^// variant ([a-z0-9_]+) (.+)$" "\\2" defines "${line}")
      string(REPLACE " " "|-D" defines "${defines}")
      list(APPEND builds "${stem}_${suffix}${stage}|-D${defines}")
    endforeach()
    foreach(build ${builds})
      string(REPLACE "|" ";" build "${build}")
      list(POP_FRONT build output_name)
      set(define_flags ${build})
      string(REPLACE "." "_" array_name ${output_name})
      set(header ${spirv_dir}/${output_name}.spv.h)
      add_custom_command(
        OUTPUT ${header}
        COMMAND ${GLSLANG_VALIDATOR} --quiet -V --target-env vulkan1.3 -g0 ${define_flags}
                -I${source_dir} -I${SHADOWGRAPH_SHADER_DIR} --vn ${array_name} -o ${header} ${source}
        DEPENDS ${source} ${includes}
        COMMENT "glslang ${output_name}"
        VERBATIM)
      list(APPEND headers ${header})
    endforeach()
  endforeach()
  add_custom_target(${target}_spirv DEPENDS ${headers})
  add_library(${target} INTERFACE)
  add_dependencies(${target} ${target}_spirv)
  target_include_directories(${target} INTERFACE $<BUILD_INTERFACE:${include_root}>)
endfunction()
