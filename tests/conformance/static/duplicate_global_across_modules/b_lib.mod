MODULE b_lib
  VAR num total := 1;
ENDMODULE
