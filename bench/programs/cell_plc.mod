MODULE CellPlc
  ! PLC task of the cell: announces parts, watches the gripper and blinks a lamp
  ! while the motion task works.
  PERS bool bPartReady;
  PERS bool bGripperOk;
  VAR num nFed := 0;
  VAR num nBlink := 0;
  VAR signaldi diPart;
  VAR signaldi diGripper;
  VAR signaldo doLamp;

  PROC main()
    AliasIO "DI_PART", diPart;
    AliasIO "DI_GRIPPER", diGripper;
    AliasIO "DO_LAMP", doLamp;
    WHILE TRUE DO
      IF NOT bPartReady AND diPart = 1 THEN
        nFed := (nFed + 1) MOD 4;
        bPartReady := TRUE;
      ENDIF
      bGripperOk := diGripper = 1;
      nBlink := (nBlink + 1) MOD 3;
      IF nBlink = 0 THEN
        SetDO doLamp, 1 - doLamp;
      ENDIF
    ENDWHILE
  ENDPROC
ENDMODULE
