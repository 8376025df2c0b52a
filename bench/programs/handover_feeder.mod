MODULE HandoverFeeder
  PERS bool part_ready := FALSE;
  VAR num fed := 0;
  PROC main()
    WHILE fed < 3 DO
      WaitUntil NOT part_ready;
      fed := fed + 1;
      part_ready := TRUE;
    ENDWHILE
  ENDPROC
ENDMODULE
