MODULE MainModule
  ! Tests: ACos(-1.5) is a recoverable run-time error (Value must lie in [-1, 1]).
  PROC main()
    VAR num a;
    a := ACos(-1.5);
    TPWrite "not reached";
  ERROR
    TPWrite "error in ACos";
  ENDPROC
ENDMODULE
