! expect: RMC101 line 5
MODULE m
  FUNC num f()
    RETURN 1;
  BACKWARD
    Stop;
  ENDFUNC
ENDMODULE
