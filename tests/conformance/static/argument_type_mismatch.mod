MODULE argument_type_mismatch
  ! Tests: passing a bool to a num parameter is a type mismatch (RMC206).
  PROC show(num v)
    TPWrite "v=" \Num:=v;
  ENDPROC
  PROC main()
    TPWrite "never printed";
    show TRUE;  ! <-- error
  ENDPROC
ENDMODULE
