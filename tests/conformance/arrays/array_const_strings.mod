MODULE array_const_strings
  ! Tests: a CONST array of strings initialised by an aggregate; elements
  ! read in a loop and concatenated.
  CONST string words{3} := ["red", "green", "blue"];
  PROC main()
    VAR string s := "";
    FOR i FROM 3 TO 1 STEP -1 DO
      s := s + words{i} + ";";
    ENDFOR
    TPWrite s;
  ENDPROC
ENDMODULE
