MODULE conformant_array_dim
  ! Tests: {*} and {*,*} parameters accept arrays of any size; Dim(arr, d)
  ! returns the size of dimension d.
  FUNC num total(num arr{*})
    VAR num s := 0;
    FOR i FROM 1 TO Dim(arr, 1) DO
      s := s + arr{i};
    ENDFOR
    RETURN s;
  ENDFUNC
  FUNC num cells(num m{*,*})
    RETURN Dim(m, 1) * Dim(m, 2);
  ENDFUNC
  PROC main()
    VAR num three{3} := [1, 2, 3];
    VAR num five{5} := [1, 1, 1, 1, 1];
    VAR num grid{2, 4};
    TPWrite "total3=" \Num:=total(three);
    TPWrite "total5=" \Num:=total(five);
    TPWrite "cells=" \Num:=cells(grid);
  ENDPROC
ENDMODULE
