MODULE Prog
  VAR robtarget pos;
  CONST robtarget pHome := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST jointtarget jHome := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    WHILE TRUE DO
      MoveJ pHome, v1000, fine, tool0;
      pos := CRobT();
      pos.trans.z := pos.trans.z + 100;
      MoveL pos, v100, fine, tool0;
    ENDWHILE
  ENDPROC
ENDMODULE
