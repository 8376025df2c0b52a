MODULE VmFallbackMix
    ! Statements a step machine runs itself (assignments to data named
    ! directly, conditions) interleaved with ones it leaves to the general
    ! step: array elements, record components, Incr/Decr, predefined
    ! functions, PERS data, an array index out of range.
    CONST num SIZE := 3;
    VAR num slots{SIZE} := [0, 0, 0];
    VAR pos offset := [0, 0, 0];
    PERS num persisted := 0;
    VAR num index := 1;
    VAR num total := 0;
    VAR num magnitude := 0;
    VAR bool upper := FALSE;
    VAR string word := "abc";

    PROC main()
        WHILE TRUE DO
            IF DInput(di_step) = 1 THEN
                Incr index;
            ELSE
                Decr index;
            ENDIF
            IF index < 1 index := SIZE;
            slots{index} := slots{index} + 1;
            IF slots{index} > 2 slots{index} := 0;
            total := slots{1} + slots{2} * 3 + slots{3} * 9;
            offset.x := -total;
            magnitude := Abs(offset.x) + Round(0.5);
            persisted := magnitude MOD 4;
            upper := word = "ABC";
            IF DInput(di_case) = 1 THEN
                word := StrMap(word, "abc", "ABC");
            ELSE
                word := "abc";
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
