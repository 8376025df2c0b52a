MODULE var_parameter_whole_array
  ! Tests: a whole array passed to a VAR {*} parameter is updated in place;
  ! Dim gives the caller's array length inside the routine.
  PROC fill(VAR num arr{*}, num start)
    FOR i FROM 1 TO Dim(arr, 1) DO
      arr{i} := start + i;
    ENDFOR
  ENDPROC
  PROC main()
    VAR num small{2};
    VAR num big{4};
    fill small, 0;
    fill big, 10;
    TPWrite "small{2}=" \Num:=small{2};
    TPWrite "big{4}=" \Num:=big{4};
  ENDPROC
ENDMODULE
