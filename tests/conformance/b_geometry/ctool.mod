MODULE MainModule
  ! Tests: CTool returns the active tool: tool0 at start, then the tool of the last move.
  PERS tooldata tGrip := [TRUE,[[0,0,150],[1,0,0,0]],[2,[0,0,50],[1,0,0,0],0,0,0]];
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR tooldata active;
    active := CTool();
    TPWrite "start mass=" \Num:=active.tload.mass;
    TPWrite "start is tool0=" \Bool:=active = tool0;
    MoveJ p10, v100, fine, tGrip;
    active := CTool();
    TPWrite "mass=" \Num:=active.tload.mass;
    TPWrite "tcp=" \Pos:=active.tframe.trans;
  ENDPROC
ENDMODULE
