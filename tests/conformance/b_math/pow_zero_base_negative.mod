MODULE MainModule
  ! Tests: Pow with base 0 and exponent <= 0 is a run-time error, caught by the handler.
  PROC main()
    VAR num x;
    x := Pow(0, -1);
    TPWrite "not reached";
  ERROR
    TPWrite "error in Pow";
  ENDPROC
ENDMODULE
