MODULE unknown_function
  ! Tests: a call of an undeclared function in an expression is a static
  ! error (unknown routine, RMC203).
  PROC main()
    VAR num x;
    TPWrite "never printed";
    x := NoSuchFunc(2) + 1;  ! <-- error
  ENDPROC
ENDMODULE
