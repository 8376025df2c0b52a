MODULE Plc
  PERS bool part_ready := FALSE;
  PROC main()
    WaitUntil NOT part_ready;
    part_ready := TRUE;
  ENDPROC
  ! a service routine of the PLC task: --entry names routines of the main task only
  PROC ResetPlc()
    part_ready := FALSE;
  ENDPROC
ENDMODULE
