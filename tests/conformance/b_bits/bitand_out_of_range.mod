MODULE MainModule
  ! Tests: a byte argument outside 0..255 is a run-time error (error number undocumented).
  PROC main()
    VAR num b;
    TPWrite "before";
    b := BitAnd(256, 1);
    TPWrite "not reached";
  ENDPROC
ENDMODULE
