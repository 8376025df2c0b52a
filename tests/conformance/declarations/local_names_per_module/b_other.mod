MODULE b_other
  LOCAL VAR num x := 2;
  LOCAL PROC show()
    TPWrite "b sees " \Num:=x;
  ENDPROC
  PROC ShowB()
    show;
  ENDPROC
ENDMODULE
