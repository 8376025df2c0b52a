MODULE HandoverRobot
  PERS bool part_ready := FALSE;
  PERS num parts := 0;
  VAR num cycle := 0;
  PROC main()
    WHILE parts < 3 DO
      WaitUntil part_ready;
      parts := parts + 1;
      part_ready := FALSE;
      ! its own bookkeeping, between hand-overs
      cycle := (cycle + 1) MOD 4;
    ENDWHILE
  ENDPROC
ENDMODULE
