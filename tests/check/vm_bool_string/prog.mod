MODULE VmBoolString
    ! Boolean operators and comparisons of bool, num and string data, over
    ! two free inputs read afresh each pass.
    VAR bool a := FALSE;
    VAR bool b := FALSE;
    VAR bool both := FALSE;
    VAR bool either := FALSE;
    VAR bool odd := FALSE;
    VAR bool same := TRUE;
    VAR bool differ := FALSE;
    VAR bool notfirst := FALSE;
    VAR bool chain := FALSE;
    VAR num count := 0;
    VAR string word := "";
    VAR string joined := "";
    VAR string tail := "c";
    VAR bool match := FALSE;
    VAR string long := "";

    PROC main()
        WHILE TRUE DO
            a := DInput(di_a) = 1;
            b := DInput(di_b) = 1;
            both := a AND b;
            either := a OR b;
            odd := a XOR b;
            same := a = b;
            differ := a <> b;
            notfirst := NOT a AND b;
            chain := a OR b XOR TRUE;
            count := 0;
            IF a count := count + 1;
            IF b count := count + 2;
            IF count = 3 THEN
                word := "ab";
            ELSEIF count = 0 THEN
                word := "";
            ELSE
                word := "a";
            ENDIF
            joined := word + tail;
            match := joined = "ab" + tail;
            IF both AND long <> "" long := long + "0123456789012345678901234567890123456789";
            IF NOT either long := "0123456789012345678901234567890123456789";
        ENDWHILE
    ENDPROC
ENDMODULE
