MODULE AxisSelect
  ! Our own program in the style of a casts library (survey round 8): a value is compared in
  ! turn with constants of a module not given (IF ... ELSEIF, and TEST ... CASE).
  VAR num nAxis := 2;
  VAR num nStation := 1;
  VAR pos vDir := [0,0,0];
  VAR string sStation := "";

  PROC main()
    IF nAxis = axisX THEN
      vDir := [1,0,0];
    ELSEIF nAxis = axisY THEN
      vDir := [0,1,0];
    ELSEIF nAxis = axisZ THEN
      vDir := [0,0,1];
    ENDIF
    TEST nStation
    CASE STATION_LOAD:
      sStation := "load";
    CASE STATION_UNLOAD:
      sStation := "unload";
    ENDTEST
  ENDPROC
ENDMODULE
