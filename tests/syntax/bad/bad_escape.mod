! expect: RMC103 line 3
MODULE m
  CONST string s := "tab\t";
ENDMODULE
