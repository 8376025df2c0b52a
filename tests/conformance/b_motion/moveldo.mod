MODULE MainModule
  ! Tests: MoveLDO sets the digital output to Value (here 0 after a Set) at the end of the move.
  CONST robtarget p20 := [[600,-100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR signaldo doGrip;
  PROC main()
    AliasIO "DO1", doGrip;
    Set doGrip;
    TPWrite "before=" \Num:=DOutput(doGrip);
    MoveLDO p20, v100, fine, tool0, doGrip, 0;
    TPWrite "after=" \Num:=DOutput(doGrip);
    TPWrite "at=" \Pos:=CPos();
  ENDPROC
ENDMODULE
