# Writes a C++ source that holds a binary file as an array:
#   cmake -DINPUT=file.bin -DOUTPUT=file.cpp -DNAME=kName -P embed_binary.cmake
# defines pds::detail::NAME (const unsigned char[]) and pds::detail::NAMESize
# (its length, std::size_t). Used for the Sobol direction numbers
# (data/sobol/), so the table ships as compact data, not as a source listing.
file(READ "${INPUT}" hex HEX)
string(LENGTH "${hex}" digits)
math(EXPR bytes "${digits} / 2")
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," body "${hex}")
string(REGEX REPLACE "((0x..,){32})" "\\1\n" body "${body}")
file(WRITE "${OUTPUT}.tmp"
  "// Generated from ${INPUT} by cmake/embed_binary.cmake: do not edit.\n"
  "#include <cstddef>\n"
  "namespace pds::detail {\n"
  "extern const unsigned char ${NAME}[];\n"
  "extern const std::size_t ${NAME}Size;\n"
  "const unsigned char ${NAME}[] = {\n${body}};\n"
  "const std::size_t ${NAME}Size = ${bytes};\n"
  "}  // namespace pds::detail\n")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
