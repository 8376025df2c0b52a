MODULE Prog
  ! The position read back is stored in a PERS, which the task Watch reads.
  PERS robtarget pLast := [[0, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST robtarget pHome := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    WHILE TRUE DO
      MoveJ pHome, v1000, fine, tool0;
      pLast := CRobT();
      MoveL Offs(pLast, 0, 0, 100), v100, fine, tool0;
      pLast := CRobT();
    ENDWHILE
  ENDPROC
ENDMODULE
