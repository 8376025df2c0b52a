MODULE OptionalCase
  PERS tooldata gripper := [TRUE, [[0, 0, 150], [1, 0, 0, 0]], [1.5, [0, 0, 60], [1, 0, 0, 0], 0, 0, 0]];
  PERS wobjdata table := [FALSE, TRUE, "", [[0, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
  CONST robtarget home := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

  PROC main()
    MoveL home, v100, fine, gripper \wobj:=table;  ! expect: RMC803
    MoveL home, v100, fine, gripper \WObj:=table;
    TPWrite "n = " \num:=3;  ! expect: RMC803
    Park \Slow;
    Park \SLOW;  ! expect: RMC803
  ENDPROC

  PROC Park(\switch Slow)
    IF Present(Slow) THEN
      MoveL home, v100, fine, gripper;
    ENDIF
  ENDPROC
ENDMODULE
