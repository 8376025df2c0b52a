MODULE GantryMove
  ! Issue 28: a component read by its own components (jTemp.JointG.extax) first gets a record
  ! type the stubs invent; once .robax and .extax show it is a jointtarget, that type
  ! replaces the invented one everywhere, also in the parameter of the missing routine
  ! the component is passed to (the written module used to name the dropped invented type).
  PROC main()
    VAR gantrygroup jTemp;
    jTemp.JointG.extax.eax_c := jTemp.JointG.extax.eax_c - 130;
    jTemp.JointG.robax.rax_1 := 0;
    MoveGantry \Gantry:=jTemp.JointG, v100;
  ENDPROC
ENDMODULE
