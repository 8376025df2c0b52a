MODULE MainModule
  ! Tests: an uncaught ERR_WAIT_MAXTIME from WaitUntil stops the program (exit code 1).
  PROC main()
    TPWrite "waiting";
    WaitUntil FALSE \MaxTime:=0.2;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
