MODULE tray_sorter
  ! A tray sorter in the style of the survey's conveyor cells: the PLC's recipe
  ! number arrives on a group input read only by TEST with numeric CASEs, and the
  ! conveyor is a mechanical unit of the motion configuration (ActUnit CNV1).
  PERS wobjdata wobjBelt := [FALSE,FALSE,"CNV1",[[0,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  CONST robtarget pGrab := [[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pTrayA := [[400,0,100],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pTrayB := [[400,300,100],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS num nInA := 0;
  PERS num nInB := 0;

  PROC main()
    WHILE nInA < 2 OR nInB < 2 DO
      TEST giRecipe
      CASE 1:
        IF nInA < 2 THEN
          Sort pTrayA;
          Incr nInA;
        ENDIF
      CASE 2:
        IF nInB < 2 THEN
          Sort pTrayB;
          Incr nInB;
        ENDIF
      ENDTEST
    ENDWHILE
  ENDPROC

  PROC Sort(robtarget pTray)
    ActUnit CNV1;
    WaitWObj wobjBelt;
    MoveL pGrab, v500, fine, tool0 \WObj:=wobjBelt;
    SetDO doVacuum, 1;
    DropWObj wobjBelt;
    DeactUnit CNV1;
    MoveL pTray, v500, fine, tool0;
    SetDO doVacuum, 0;
  ENDPROC
ENDMODULE
