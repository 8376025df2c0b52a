MODULE VmLocalsRoutines
    ! Routines with base data and parameters, called in a loop; a FUNC's
    ! result in an assignment; GOTO and labels; compact IF; IF/ELSEIF.
    VAR num total := 0;
    VAR num calls := 0;
    VAR num grade := 0;
    VAR num doubled := 0;
    VAR num jumps := 0;
    VAR num last := 0;

    PROC main()
        VAR num pass := 0;
        VAR bool odd := FALSE;

        WHILE TRUE DO
            pass := pass + 1;
            IF pass > 3 pass := 1;
            odd := pass MOD 2 = 1;
            Accumulate pass, total;
            doubled := Twice(pass) + Twice(DInput(di_bump));
            Classify doubled;
            jumps := 0;
        again:
            jumps := jumps + 1;
            IF jumps < pass GOTO again;
            IF odd THEN
                GOTO skip;
            ENDIF
            last := pass;
        skip:
        ENDWHILE
    ENDPROC

    PROC Accumulate(num amount, INOUT num sum)
        VAR num base := 10;

        base := base + amount;
        sum := base - 10 + sum MOD 6;
        calls := calls + 1;
        IF calls >= 3 calls := 0;
    ENDPROC

    FUNC num Twice(num x)
        VAR num result;

        FOR k FROM 1 TO 2 DO
            result := result + x;
        ENDFOR
        RETURN result;
    ENDFUNC

    PROC Classify(num value)
        IF value < 2 THEN
            grade := 1;
        ELSEIF value < 4 THEN
            grade := 2;
        ELSEIF value = 4 OR value = 5 THEN
            grade := 3;
        ELSE
            grade := 4;
        ENDIF
    ENDPROC
ENDMODULE
