MODULE Prog
  VAR num tab{2} := [1, 2];
  VAR num i := 1;
  CONST robtarget pHome := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST jointtarget jHome := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  FUNC num Height()
    RETURN CRobT().trans.z;
  ENDFUNC

  PROC main()
    WHILE TRUE DO
      MoveJ pHome, v1000, fine, tool0;
      MoveL Offs(CRobT(), 0, 0, 100), v100, fine, tool0;
      IF Height() > 650 i := 3;
      tab{i} := 0;
    ENDWHILE
  ENDPROC
ENDMODULE
