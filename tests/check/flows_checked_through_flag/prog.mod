MODULE Flag
  ! The check's result goes through a flag: lint (flow-insensitive, RMC820) reports the
  ! move, the state graph shows that only a checked height reaches it.
  VAR iodev channel;
  PERS tooldata gripper := [TRUE, [[0, 0, 150], [1, 0, 0, 0]], [1.5, [0, 0, 60], [1, 0, 0, 0], 0, 0, 0]];
  CONST robtarget home := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

  PROC main()
    VAR num height;
    VAR bool safe := FALSE;
    Open "com1:", channel \Read;
    height := ReadNum(channel \Time:=5);
    IF height >= 0 AND height <= 300 THEN
      safe := TRUE;
    ENDIF
    IF safe THEN
      MoveL Offs(home, 0, 0, height), v100, fine, gripper;
    ENDIF
  ERROR
    RETURN;
  ENDPROC
ENDMODULE
