! Task 2: logs each move the robot task reports, waiting for one at most a minute.
MODULE logger
  PERS bool moved := FALSE;
  VAR num logged := 0;
  VAR bool idle := FALSE;
  PROC main()
    WHILE TRUE DO
      WaitUntil moved \MaxTime:=60 \TimeFlag:=idle;
      IF NOT idle THEN
        logged := (logged + 1) MOD 2;
        moved := FALSE;
      ENDIF
    ENDWHILE
  ENDPROC
ENDMODULE
