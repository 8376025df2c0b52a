module case_insensitive_names
  ! Tests: RAPID is case-insensitive: keywords, data names, routine names,
  ! type names and predefined routines match regardless of case.
  var NUM Counter := 1;
  proc Bump()
    COUNTER := counter + 1;
  endproc
  PROC Main()
    bump;
    BUMP;
    tpwrite "counter=" \num:=cOuNtEr;
    IF counter = 3 THEN
      TPWRITE "three";
    endif
  ENDPROC
ENDMODULE
