MODULE b_lib
  PERS num shared := 4;
  PROC IncShared()
    shared := shared + 1;
  ENDPROC
ENDMODULE
