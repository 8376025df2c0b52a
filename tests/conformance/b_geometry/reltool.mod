MODULE MainModule
  ! Tests: RelTool displaces a robtarget along the axes of its own tool frame: with identity
  ! orientation the offsets add directly; rotated 180 degrees about x, y and z offsets flip sign.
  CONST robtarget p1 := [[100,200,300],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[100,200,300],[0,1,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR robtarget r;
    r := RelTool(p1, 10, 20, 100);
    TPWrite "identity=" \Pos:=r.trans;
    r := RelTool(p2, 10, 20, 100);
    TPWrite "flipped=" \Pos:=r.trans;
    TPWrite "rot kept=" \Bool:=r.rot = p2.rot;
  ENDPROC
ENDMODULE
