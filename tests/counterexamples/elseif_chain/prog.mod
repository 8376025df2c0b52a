MODULE prog
  ! the operator picks a station; station 5 has no slot yet
  VAR num station;
  VAR num slot;
  VAR num parts{4} := [0, 0, 0, 0];

  PROC main()
    TPReadNum station, "Station?";
    IF station = 1 THEN
      slot := 1;
    ELSEIF station = 2 THEN
      slot := 2;
    ELSEIF station = 3 THEN
      slot := 3;
    ELSEIF station = 4 THEN
      slot := 4;
    ELSEIF station = 5 THEN
      parts{slot} := parts{slot} + 1;
    ENDIF
  ENDPROC
ENDMODULE
