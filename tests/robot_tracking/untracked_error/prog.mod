MODULE Prog
  ! Moves relative to where the robot is; the index error is in data of its own.
  VAR signaldi diPart;
  VAR num tab{3} := [1, 2, 3];
  VAR num n := 0;
  VAR robtarget pos;
  VAR jointtarget jpos;
  CONST robtarget pHome := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST jointtarget jHome := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    AliasIO "DI_PART", diPart;
    WHILE TRUE DO
      pos := CRobT(\Tool:=tool0);
      pos.trans.z := pos.trans.z - 250;
      MoveL pos, v100, fine, tool0;
      jpos := CJointT();
      jpos.robax.rax_6 := jpos.robax.rax_6 + 90;
      MoveAbsJ jpos, v100, fine, tool0;
      IF diPart = 1 n := n + 1;
      MoveL Offs(CRobT(), 0, 0, 250), v100, z10, tool0;
      tab{n + 1} := n;
      IF tab{1} <> 0 n := 0;
      IF n = 3 n := 0;
    ENDWHILE
  ENDPROC
ENDMODULE
