MODULE Prog
  VAR num tab{2} := [1, 2];
  VAR num i := 1;
  VAR robtarget pos;
  VAR robtarget copy;
  CONST robtarget pHome := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST jointtarget jHome := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    WHILE TRUE DO
      MoveJ pHome, v1000, fine, tool0;
      pos := CRobT();
      MoveL Offs(pos, 0, 0, 100), v100, fine, tool0;
      GetDataVal "pos", copy;
      IF copy.trans.z > 550 i := 3;
      tab{i} := 0;
    ENDWHILE
  ENDPROC
ENDMODULE
