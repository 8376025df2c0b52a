MODULE Prog
  ! Glue runs only when MoveLSync reaches p10, which names it by a string: with the
  ! answers 1 and 2 it never runs, but with 0 it does (not a service routine).
  CONST robtarget p10 := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  VAR num answer := 0;
  VAR num glued := 0;
  PROC main()
    TPReadNum answer, "glue?";
    IF answer = 0 MoveLSync p10, v100, fine, tool0, "Glue";
  ENDPROC
  PROC Glue()
    glued := glued + 1;
  ENDPROC
ENDMODULE
