MODULE Hmi
  ! nCmdInput is also written a computed value (nCmdInput * 2): the loaded code might end the
  ! wait itself, so the wait is not taken as one only a client ends, and as the computed
  ! value is always 0 here, the deadlock is found.
  PERS num nCmdInput := 0;
  PROC main()
    nCmdInput := 0;
    nCmdInput := nCmdInput * 2;
    WaitUntil nCmdInput <> 0;
  ENDPROC
ENDMODULE
