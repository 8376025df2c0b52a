MODULE recursion_factorial
  ! Tests: a function may call itself recursively; each activation has its
  ! own parameters.
  FUNC num fact(num n)
    IF n <= 1 RETURN 1;
    RETURN n * fact(n - 1);
  ENDFUNC
  PROC main()
    TPWrite "5!=" \Num:=fact(5);
    TPWrite "10!=" \Num:=fact(10);
  ENDPROC
ENDMODULE
