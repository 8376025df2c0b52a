MODULE alias_num
  ! Tests: ALIAS num level makes level the same type as num: values mix
  ! freely in arithmetic and assignment in both directions.
  ALIAS num level;
  VAR level l := 3;
  PROC main()
    VAR num n;
    l := l * 2;
    n := l + 1;
    l := n;
    TPWrite "n=" \Num:=n;
    TPWrite "l=" \Num:=l;
  ENDPROC
ENDMODULE
