MODULE MainModule
  ! Tests: Incr adds 1 to a num variable, an array element, a record component, and a dnum.
  PROC main()
    VAR num n := 0;
    VAR num arr{2} := [10, 20];
    VAR pos p := [1, 2, 3];
    VAR dnum d := 8388608;
    Incr n;
    Incr n;
    Incr arr{1};
    Incr p.y;
    Incr d;
    TPWrite "n=" \Num:=n;
    TPWrite "arr1=" \Num:=arr{1};
    TPWrite "py=" \Num:=p.y;
    TPWrite "d=" \Dnum:=d;
  ENDPROC
ENDMODULE
