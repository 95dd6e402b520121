# ag_protobuf_cpp(<out_var> <file.proto>): generates the C++ of a .proto that
# lives beside the code that uses it (not in proto/) into
# build/generated/<its folder>, and sets <out_var> to the .pb.cc to list among
# a library's sources; the library includes ${CMAKE_BINARY_DIR}/generated.
function(ag_protobuf_cpp out_var proto)
  file(RELATIVE_PATH relative ${CMAKE_SOURCE_DIR} ${proto})
  get_filename_component(folder ${relative} DIRECTORY)
  get_filename_component(name ${proto} NAME_WE)
  set(out ${CMAKE_BINARY_DIR}/generated/${folder})
  add_custom_command(
    OUTPUT ${out}/${name}.pb.cc ${out}/${name}.pb.h
    COMMAND ${CMAKE_COMMAND} -E make_directory ${out}
    COMMAND protobuf::protoc --proto_path=${CMAKE_SOURCE_DIR}
            --cpp_out=${CMAKE_BINARY_DIR}/generated ${proto}
    DEPENDS ${proto} protobuf::protoc
    COMMENT "protoc ${name}.proto")
  set(${out_var} ${out}/${name}.pb.cc PARENT_SCOPE)
endfunction()
