%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%

MODULE Hello
  ! A small pick-and-place greeting: move over three points, count the parts.
  CONST robtarget pHome := [[500,0,600],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pPick := [[600,-200,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pPlace := [[600,200,300],[0,0,1,0],[-1,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS num nParts := 0;
  CONST num MAX_PARTS := 3;

  PROC main()
    VAR num i;
    TPWrite "Hello from RAPID";
    MoveJ pHome, v1000, z50, tool0;
    FOR i FROM 1 TO MAX_PARTS DO
      MoveL Offs(pPick, 0, 0, 50), v500, z10, tool0;
      MoveL pPick, v100, fine, tool0;
      MoveL pPlace, v500, z10, tool0 \WObj:=wobj0;
      nParts := nParts + 1;
      TPWrite "Parts moved: "\Num:=nParts;
    ENDFOR
    IF nParts >= MAX_PARTS THEN
      TPWrite "Done";
    ELSE
      TPWrite "Stopped early";
    ENDIF
    MoveJ pHome, v1000, fine, tool0;
  ENDPROC
ENDMODULE
