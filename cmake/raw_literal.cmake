# al_raw_literal(TEXT DELIM OUT): OUT is TEXT as consecutive C++ raw string literals with
# delimiter DELIM, one per 16 KiB chunk, which keeps every literal within compilers' limits.
function(al_raw_literal text delim out)
  string(LENGTH "${text}" len)
  set(chunks "")
  set(pos 0)
  while(pos LESS len)
    string(SUBSTRING "${text}" ${pos} 16000 piece)
    string(APPEND chunks "R\"${delim}(${piece})${delim}\"\n")
    math(EXPR pos "${pos} + 16000")
  endwhile()
  set(${out} "${chunks}" PARENT_SCOPE)
endfunction()
