MODULE AlarmCell
  ! One task driven by interrupts: a part sensor and a stop button (rising edges)
  ! and a cyclic timer each run a TRAP while the main loop moves the robot.
  VAR intnum iPart;
  VAR intnum iStop;
  VAR intnum iTick;
  VAR signaldi diPart;
  VAR signaldi diStop;
  VAR num nParts := 0;
  VAR num nStops := 0;
  VAR num nTicks := 0;
  VAR bool bStopped := FALSE;
  CONST robtarget pA := [[500,0,400],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pB := [[0,500,400],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

  PROC main()
    AliasIO "DI_PART", diPart;
    AliasIO "DI_STOP", diStop;
    CONNECT iPart WITH OnPart;
    ISignalDI diPart, 1, iPart;
    CONNECT iStop WITH OnStop;
    ISignalDI diStop, 1, iStop;
    CONNECT iTick WITH OnTick;
    ITimer 1, iTick;
    WHILE TRUE DO
      IF bStopped THEN
        WaitTime 0.5;
        bStopped := FALSE;
      ELSE
        MoveJ pA, v1000, z10, tool0;
        MoveJ pB, v1000, z10, tool0;
      ENDIF
    ENDWHILE
  ENDPROC

  TRAP OnPart
    nParts := (nParts + 1) MOD 3;
  ENDTRAP

  TRAP OnStop
    bStopped := TRUE;
    nStops := (nStops + 1) MOD 2;
  ENDTRAP

  TRAP OnTick
    nTicks := (nTicks + 1) MOD 2;
  ENDTRAP
ENDMODULE
