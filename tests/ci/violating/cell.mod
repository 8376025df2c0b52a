MODULE Cell
  VAR num nParts := 0;

  PROC main()
    WHILE nParts < 5 DO
      nParts := nParts + 1;
    ENDWHILE
    RETURN;
    nParts := 0;
  ENDPROC
ENDMODULE
