MODULE too_many_function_arguments
  ! Tests: calling a function with more arguments than parameters is a
  ! static error (RMC205).
  FUNC num sq(num v)
    RETURN v * v;
  ENDFUNC
  PROC main()
    VAR num x;
    TPWrite "never printed";
    x := sq(2, 3);  ! <-- error
  ENDPROC
ENDMODULE
