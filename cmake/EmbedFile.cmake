# Generates a .cpp that holds the contents of a data file as a string, so the core can use data
# (materials, birds, pigs) without looking for files at run time.
# Usage: cmake -DINPUT=... -DOUTPUT=... -DSYMBOL=... -P EmbedFile.cmake
file(READ "${INPUT}" content)
file(WRITE "${OUTPUT}.tmp"
     "// Generated from ${INPUT}; edit that file instead.\n"
     "namespace abalike::embedded { extern const char* const ${SYMBOL}; const char* const ${SYMBOL} = R\"abalike_json(${content})abalike_json\"; }\n")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
