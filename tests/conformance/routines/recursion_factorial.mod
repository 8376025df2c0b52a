MODULE recursion_factorial
  ! Tests: a function may call itself recursively; each activation has its
  ! own parameters. (10! = 3628800 is compared, not printed: how 7-digit
  ! integers print is not documented.)
  FUNC num fact(num n)
    IF n <= 1 RETURN 1;
    RETURN n * fact(n - 1);
  ENDFUNC
  PROC main()
    TPWrite "5!=" \Num:=fact(5);
    TPWrite "7!=" \Num:=fact(7);
    TPWrite "10!=3628800 " \Bool:=fact(10) = 3628800;
  ENDPROC
ENDMODULE
