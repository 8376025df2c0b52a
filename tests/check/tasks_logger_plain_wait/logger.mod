! Task 2: logs each move the robot task reports, waiting for it without a time-out.
MODULE logger
  PERS bool moved := FALSE;
  VAR num logged := 0;
  PROC main()
    WHILE TRUE DO
      WaitUntil moved;
      logged := (logged + 1) MOD 2;
      moved := FALSE;
    ENDWHILE
  ENDPROC
ENDMODULE
