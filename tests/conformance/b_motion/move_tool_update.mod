MODULE MainModule
  ! Tests: a move instruction makes its Tool argument the active tool (CTool), for MoveJ then MoveL.
  PERS tooldata tA := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,10],[1,0,0,0],0,0,0]];
  PERS tooldata tB := [TRUE,[[0,0,200],[1,0,0,0]],[3,[0,0,20],[1,0,0,0],0,0,0]];
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR tooldata t;
    MoveJ p10, v100, fine, tA;
    t := CTool();
    TPWrite "after MoveJ mass=" \Num:=t.tload.mass;
    MoveL p10, v100, fine, tB;
    t := CTool();
    TPWrite "after MoveL mass=" \Num:=t.tload.mass;
  ENDPROC
ENDMODULE
