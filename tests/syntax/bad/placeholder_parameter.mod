! expect: RMC106 line 3
MODULE m
  PROC main(<PAR>)
  ENDPROC
ENDMODULE
