MODULE Prog
  VAR num tab{2} := [1, 2];
  VAR num i := 1;
  VAR jointtarget jpos;
  VAR jointtarget jx;
  CONST robtarget pHome := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST jointtarget jHome := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    WHILE TRUE DO
      MoveAbsJ jHome, v1000, fine, tool0;
      jpos := CJointT();
      jpos.robax.rax_1 := jpos.robax.rax_1 + 90;
      MoveAbsJ jpos, v100, fine, tool0;
      jx := CalcJointT(pHome, tool0);
      IF jx.robax.rax_1 > 45 i := 3;
      tab{i} := 0;
    ENDWHILE
  ENDPROC
ENDMODULE
