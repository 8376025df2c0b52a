MODULE b_lib
  VAR num g := 2;
  PROC ShowG()
    TPWrite "b: g=" \Num:=g;
  ENDPROC
ENDMODULE
