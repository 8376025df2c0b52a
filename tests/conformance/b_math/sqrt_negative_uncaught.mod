MODULE MainModule
  ! Tests: Sqrt of a negative value is a run-time error (the manual requires Value >= 0;
  ! the error number is undocumented, so only the uncaught error is checked).
  PROC main()
    VAR num x;
    TPWrite "before";
    x := Sqrt(-1);
    TPWrite "not reached";
  ENDPROC
ENDMODULE
