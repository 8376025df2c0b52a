MODULE Prog
  ! Turns joint 4 back by module data that routines write, each time with a value of a known
  ! size: a constant, or a product of other such data (quarter, proven first). The difference
  ! cannot leave the range of num, so nothing but moves sees where the robot is.
  VAR num quarter := 1;
  VAR num turn := 360;
  VAR num n := 0;
  VAR jointtarget jpos;
  PROC main()
    Setup;
    WHILE TRUE DO
      jpos := CJointT();
      jpos.robax.rax_4 := jpos.robax.rax_4 - turn;
      MoveAbsJ jpos, v100, z50, tool0;
      n := n + 1;
      IF n = 3 THEN
        n := 0;
        turn := 90;
      ENDIF
    ENDWHILE
  ENDPROC
  PROC Setup()
    quarter := 2;
    turn := quarter * 45;
  ENDPROC
ENDMODULE
