MODULE Prog
  ! Turns joint 4 back a full turn from where it stopped, each cycle, by module data that no
  ! routine writes (TPWrite only reads it): the difference cannot leave the range of num.
  VAR num turn := 360;
  VAR num n := 0;
  VAR jointtarget jpos;
  PROC main()
    WHILE TRUE DO
      jpos := CJointT();
      jpos.robax.rax_4 := jpos.robax.rax_4 - turn;
      MoveAbsJ jpos, v100, z50, tool0;
      TPWrite "Turned: " \Num:=turn;
      n := n + 1;
      IF n = 3 n := 0;
    ENDWHILE
  ENDPROC
ENDMODULE
