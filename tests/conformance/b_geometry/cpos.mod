MODULE MainModule
  ! Tests: CPos returns the TCP position reached by the last move (tool0, wobj0), with and
  ! without explicit \Tool and \WObj.
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[600,-100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR pos here;
    MoveL p10, v100, fine, tool0;
    here := CPos();
    TPWrite "p10=" \Pos:=here;
    MoveL p20, v100, fine, tool0;
    TPWrite "p20=" \Pos:=CPos(\Tool:=tool0 \WObj:=wobj0);
  ENDPROC
ENDMODULE
