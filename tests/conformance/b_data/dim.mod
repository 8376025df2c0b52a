MODULE MainModule
  ! Tests: Dim returns the number of elements of each dimension of 1-, 2- and 3-dimensional arrays.
  VAR num one{5};
  VAR num two{2, 3};
  VAR bool three{4, 1, 6};
  PROC main()
    TPWrite "one=" \Num:=Dim(one, 1);
    TPWrite "two1=" \Num:=Dim(two, 1);
    TPWrite "two2=" \Num:=Dim(two, 2);
    TPWrite "three1=" \Num:=Dim(three, 1);
    TPWrite "three2=" \Num:=Dim(three, 2);
    TPWrite "three3=" \Num:=Dim(three, 3);
  ENDPROC
ENDMODULE
