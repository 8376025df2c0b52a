MODULE string_ordering_comparison
  ! Tests: < is defined for num and dnum only; comparing strings with < is a
  ! type mismatch (RMC206).
  PROC main()
    VAR bool b;
    TPWrite "never printed";
    b := "a" < "b";  ! <-- error
  ENDPROC
ENDMODULE
