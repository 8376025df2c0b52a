MODULE MainModule
  ! Tests: ASin(2) is a run-time error (Value must lie in [-1, 1]; error number undocumented).
  PROC main()
    VAR num a;
    TPWrite "before";
    a := ASin(2);
    TPWrite "not reached";
  ENDPROC
ENDMODULE
