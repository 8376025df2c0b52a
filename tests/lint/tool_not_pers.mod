MODULE ToolNotPers
  VAR tooldata gun := [TRUE, [[0, 0, 150], [1, 0, 0, 0]], [1.5, [0, 0, 60], [1, 0, 0, 0], 0, 0, 0]];
  PERS tooldata gripper := [TRUE, [[0, 0, 150], [1, 0, 0, 0]], [1.5, [0, 0, 60], [1, 0, 0, 0], 0, 0, 0]];
  CONST wobjdata table := [FALSE, TRUE, "", [[0, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
  PERS wobjdata fixture := [FALSE, TRUE, "", [[0, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
  CONST robtarget home := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

  PROC main()
    MoveL home, v100, fine, gun;  ! expect: RMC802
    MoveL home, v100, fine, gripper \WObj:=table;  ! expect: RMC802
    MoveJ home, v100, fine, gripper \WObj:=fixture;
    MoveL home, v100, z10, tool0;
    Approach gun;
    Depart gripper;
  ENDPROC

  PROC Approach(tooldata t)
    MoveL Offs(home, 0, 0, 100), v100, fine, t;  ! expect: RMC802
  ENDPROC

  PROC Depart(PERS tooldata t)
    MoveL Offs(home, 0, 0, 100), v100, fine, t;
  ENDPROC
ENDMODULE
