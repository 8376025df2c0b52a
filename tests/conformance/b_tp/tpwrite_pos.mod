MODULE MainModule
  ! Tests: TPWrite \Pos appends the position as [x,y,z] without spaces.
  PROC main()
    VAR pos p := [1.5, -2, 0.25];
    TPWrite "p=" \Pos:=p;
    TPWrite "" \Pos:=[1, 2, 3];
    TPWrite "x only=" \Num:=p.x;
  ENDPROC
ENDMODULE
