MODULE Prog
  ! Screws a cap on each cycle: turns joint 4 on from where it stopped, a step at a time, a
  ! full turn. The FOR's bounds are routine data that nothing writes (TPWrite only reads
  ! one): the variable is at most 360, and the angle plus it cannot leave the range of num.
  VAR num n := 0;
  PROC main()
    WHILE TRUE DO
      Screw;
      n := n + 1;
      IF n = 3 n := 0;
    ENDWHILE
  ENDPROC
  PROC Screw()
    VAR jointtarget jpos;
    VAR num start_angle;
    VAR num step_angle := 30;
    VAR num turn := 360;
    jpos := CJointT();
    start_angle := jpos.robax.rax_4;
    TPWrite "Turn: " \Num:=turn;
    FOR i FROM 1 TO turn STEP step_angle DO
      jpos.robax.rax_4 := start_angle + i;
      MoveAbsJ jpos, v100, z1, tool0;
    ENDFOR
  ENDPROC
ENDMODULE
