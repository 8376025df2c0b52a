MODULE MainModule
  ! Tests: CRobT returns the current robtarget: position and orientation of the last target.
  CONST robtarget p10 := [[500,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR robtarget now;
    MoveL p10, v100, fine, tool0;
    now := CRobT(\Tool:=tool0 \WObj:=wobj0);
    TPWrite "trans=" \Pos:=now.trans;
    TPWrite "rot=" \Orient:=now.rot;
    now := CRobT();
    TPWrite "default=" \Pos:=now.trans;
  ENDPROC
ENDMODULE
