MODULE MainModule
  ! Tests: MoveLSync calls the named procedure once per move; the name is a string expression.
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR num calls := 0;
  PROC main()
    VAR string name := "Count";
    MoveLSync p10, v100, fine, tool0, name;
    MoveLSync p10, v100, fine, tool0, "Co" + "unt";
    TPWrite "calls=" \Num:=calls;
    TPWrite "at=" \Pos:=CPos();
  ENDPROC

  PROC Count()
    Incr calls;
  ENDPROC
ENDMODULE
