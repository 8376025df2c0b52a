MODULE Warn
  ! The height is compared but an out-of-range value is only reported, not replaced:
  ! the run with an in-range height goes on with the mark still set (the IF's branch
  ! neither leaves nor assigns the height), so the property is violated.
  VAR iodev channel;
  PERS tooldata gripper := [TRUE, [[0, 0, 150], [1, 0, 0, 0]], [1.5, [0, 0, 60], [1, 0, 0, 0], 0, 0, 0]];
  CONST robtarget home := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

  PROC main()
    VAR num height;
    Open "com1:", channel \Read;
    height := ReadNum(channel \Time:=5);
    IF height > 300 THEN
      TPWrite "height too large";
    ENDIF
    MoveL Offs(home, 0, 0, height), v100, fine, gripper;
  ERROR
    RETURN;
  ENDPROC
ENDMODULE
