MODULE recursion_fibonacci
  ! Tests: doubly recursive function calls with local data per activation.
  FUNC num fib(num n)
    VAR num a;
    VAR num b;
    IF n < 2 RETURN n;
    a := fib(n - 1);
    b := fib(n - 2);
    RETURN a + b;
  ENDFUNC
  PROC main()
    TPWrite "fib(10)=" \Num:=fib(10);
  ENDPROC
ENDMODULE
