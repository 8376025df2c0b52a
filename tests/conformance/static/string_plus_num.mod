MODULE string_plus_num
  ! Tests: + between a string and a num is a type mismatch (no implicit
  ! conversion, RMC206).
  PROC main()
    VAR string s;
    TPWrite "never printed";
    s := "n=" + 5;  ! <-- error
  ENDPROC
ENDMODULE
