MODULE Rob2
  PERS num nParts := 0;
  PROC main()
    nParts := 4;
  ENDPROC
ENDMODULE
