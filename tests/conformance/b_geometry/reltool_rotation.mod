MODULE MainModule
  ! Tests: RelTool with \Rz rotates the orientation about the tool z axis and keeps the position.
  CONST robtarget p1 := [[100,200,300],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR robtarget r;
    r := RelTool(p1, 0, 0, 0 \Rz:=90);
    TPWrite "trans=" \Pos:=r.trans;
    TPWrite "z=" \Num:=Round(EulerZYX(\Z, r.rot) \Dec:=2);
    TPWrite "q1=" \Num:=Round(r.rot.q1 \Dec:=4);
    TPWrite "q4=" \Num:=Round(r.rot.q4 \Dec:=4);
  ENDPROC
ENDMODULE
