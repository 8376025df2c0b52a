MODULE MainModule
  ! Tests: WaitDO with \MaxTime on an output that never changes raises ERR_WAIT_MAXTIME;
  ! uncaught, it stops the program with exit code 1.
  VAR signaldo doReady;
  PROC main()
    AliasIO "DO1", doReady;
    TPWrite "waiting";
    WaitDO doReady, 1 \MaxTime:=0.5;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
