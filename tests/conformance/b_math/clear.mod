MODULE MainModule
  ! Tests: Clear sets a num variable, an array element and a dnum variable to 0.
  PROC main()
    VAR num reg1 := 17;
    VAR num arr{3} := [1, 2, 3];
    VAR dnum d := 4294967295;
    Clear reg1;
    Clear arr{2};
    Clear d;
    TPWrite "reg1=" \Num:=reg1;
    TPWrite "arr=" \Num:=arr{1} + arr{2} * 10 + arr{3} * 100;
    TPWrite "d=" \Dnum:=d;
  ENDPROC
ENDMODULE
