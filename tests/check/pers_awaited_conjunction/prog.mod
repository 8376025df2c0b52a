MODULE Handshake
  ! Written for the test (issue 28, held-out program 13's shape): the task clears the command
  ! word and the acknowledgement, then waits for a client to answer both. No write of the
  ! loaded code gives INST_UNKNOWN (a CONST) or TRUE, so each name of the AND is awaited
  ! from outside and the wait is no deadlock.
  CONST num INST_UNKNOWN := -1;
  PERS num GlbCommandId := 0;
  PERS bool FlagRltAck := FALSE;
  VAR num nSent := 0;

  PROC main()
    WHILE TRUE DO
      GlbCommandId := 5;
      FlagRltAck := FALSE;
      nSent := nSent + 1;
      IF nSent > 3 nSent := 0;
      WaitUntil GlbCommandId = INST_UNKNOWN AND FlagRltAck = TRUE;
    ENDWHILE
  ENDPROC
ENDMODULE
