MODULE MainModule
  ! Tests: Dim on a {*} array parameter gives the length of the array actually passed.
  PROC main()
    VAR num small{3} := [1, 2, 3];
    VAR num big{6} := [1, 2, 3, 4, 5, 6];
    VAR pos grid{2, 4};
    TPWrite "small sum=" \Num:=Sum(small);
    TPWrite "big sum=" \Num:=Sum(big);
    ShowSize grid;
  ENDPROC

  FUNC num Sum(num values{*})
    VAR num total := 0;
    FOR i FROM 1 TO Dim(values, 1) DO
      total := total + values{i};
    ENDFOR
    RETURN total;
  ENDFUNC

  PROC ShowSize(pos cells{*, *})
    TPWrite "rows=" \Num:=Dim(cells, 1);
    TPWrite "cols=" \Num:=Dim(cells, 2);
  ENDPROC
ENDMODULE
