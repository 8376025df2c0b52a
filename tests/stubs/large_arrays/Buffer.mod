MODULE Buffer
  ! Tests: stubs for a cell whose logging module was not given: the program fills a
  ! buffer of 2,000 measurements and 1,500 flags in FOR loops. Arrays of more than 1,000
  ! elements get no written value (it would be too long): a num or bool array is declared
  ! without one, as a VAR, whose elements start at 0 and FALSE; a record array is left to
  ! the user with the reason, not "type not inferred".
  PROC main()
    FOR i FROM 1 TO 2000 DO
      nSamples{i} := i;
    ENDFOR
    FOR k FROM 1 TO 1500 DO
      bSeen{k} := TRUE;
    ENDFOR
    FOR j FROM 1 TO 1200 DO
      MoveL pPath{j}, v100, fine, tool0;
    ENDFOR
  ENDPROC
ENDMODULE
