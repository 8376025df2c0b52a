MODULE Cell
  VAR num nParts := 0;

  PROC main()
    WHILE nParts < 3 DO
      nParts := nParts + 1;
    ENDWHILE
  ENDPROC
ENDMODULE
