MODULE Robot
  PERS bool part_ready := FALSE;
  PERS num picked := 0;
  PROC main()
    WaitUntil part_ready;
    picked := picked + 1;
    part_ready := FALSE;
  ENDPROC
  ! started by hand from the FlexPendant
  PROC ServicePosition()
    picked := 0;
  ENDPROC
ENDMODULE
