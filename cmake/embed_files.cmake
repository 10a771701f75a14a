# Writes a C++ source that holds each file of FILES as a string, looked up by
# its path relative to the source tree (see src/core/embedded_files.h).
set(body "#include \"core/embedded_files.h\"\n\nnamespace proxsim {\n\nconst std::map<std::string, std::string_view>& EmbeddedFiles() {\n  static const std::map<std::string, std::string_view> files = {\n")
string(REPLACE "," ";" FILES "${FILES}")
foreach(file IN LISTS FILES)
  file(READ ${ROOT}/${file} content)
  # A raw string literal keeps the file verbatim; the delimiter cannot occur in YAML or URDF.
  string(APPEND body "    {\"${file}\", R\"proxsim_embed(${content})proxsim_embed\"},\n")
endforeach()
string(APPEND body "  };\n  return files;\n}\n\n}  // namespace proxsim\n")
file(WRITE ${OUT}.tmp "${body}")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
