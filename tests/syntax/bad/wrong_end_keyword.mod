! expect: RMC101 line 6
MODULE m
  PROC main()
    WHILE TRUE DO
      Stop;
    ENDFOR
  ENDPROC
ENDMODULE
