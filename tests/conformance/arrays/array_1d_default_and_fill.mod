MODULE array_1d_default_and_fill
  ! Tests: a 1-dimensional num array starts with all elements 0, elements are
  ! indexed from 1, and can be assigned through an index expression.
  VAR num a{5};
  PROC main()
    VAR num sum := 0;
    TPWrite "a{3}=" \Num:=a{3};
    FOR i FROM 1 TO 5 DO
      a{i} := i * i;
    ENDFOR
    FOR i FROM 1 TO 5 DO
      sum := sum + a{i};
    ENDFOR
    TPWrite "sum=" \Num:=sum;
    TPWrite "a{5}=" \Num:=a{2 + 3};
  ENDPROC
ENDMODULE
