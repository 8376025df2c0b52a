MODULE Reset
  ! Tests: stubs for a cell whose display module (a system module with the operator's
  ! screen lines) was not given: the reset routine clears its eleven lines in a FOR loop,
  ! so the stub array has 11 elements, not the default 10 (Fabio-Coder's FOUNDRY.mod: a
  ! stub of 10 made 'stVideo{11}' an error the controller never raises).
  PROC main()
    FOR i FROM 1 TO 11 DO
      stVideo{i} := " ";
    ENDFOR
    FOR k FROM 3 TO 1 STEP -1 DO
      nCounts{k} := 0;
    ENDFOR
  ENDPROC
ENDMODULE
