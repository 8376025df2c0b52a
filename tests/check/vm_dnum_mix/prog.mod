MODULE VmDnumMix
    ! dnum is a double: integers beyond 2^24 stay exact; num data and
    ! num results are rounded to float32; a num and a dnum give a dnum.
    VAR dnum big := 16777216;
    VAR num narrow := 16777216;
    VAR dnum tenth := 0.1;
    VAR num ntenth := 0.1;
    VAR dnum mixed := 0;
    VAR dnum wide := 4294967297;
    VAR dnum half := 0;
    VAR dnum rest := 0;
    VAR dnum negrest := 0;
    VAR bool same := TRUE;
    VAR num done := 0;

    PROC main()
        FOR k FROM 1 TO 3 DO
            IF DInput(di_up) = 1 THEN
                big := big + 1;
            ELSE
                big := big - 1;
            ENDIF
            narrow := big;
        ENDFOR
        mixed := tenth + ntenth;
        same := tenth = ntenth;
        half := wide DIV 2;
        rest := wide MOD 2;
        negrest := -wide MOD 2;
        done := 1;
    ENDPROC
ENDMODULE
