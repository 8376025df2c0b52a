MODULE MainModule
  ! Tests: moves to targets computed in a loop (Offs of a base point) end at the last target.
  CONST robtarget base := [[500,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR pos here;
    FOR i FROM 1 TO 3 DO
      MoveL Offs(base, i * 10, 0, 0), v200, z10, tool0;
      here := CPos();
      TPWrite "x=" \Num:=here.x;
    ENDFOR
  ENDPROC
ENDMODULE
