MODULE MainModule
  ! Tests: moves accept the documented optional arguments \Conc, \V, \T, \Z and \WObj.
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[600,-100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveJ \Conc, p10, v500, z50, tool0;
    MoveL p20, v100 \V:=200, z10 \Z:=15, tool0;
    MoveL p10, v100 \T:=2, fine, tool0 \WObj:=wobj0;
    TPWrite "at=" \Pos:=CPos();
  ENDPROC
ENDMODULE
