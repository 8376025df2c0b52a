MODULE VmSignalReads
    ! Free digital inputs read in conditions and assignments, twice in one
    ! statement (one value) and in consecutive statements (a value each);
    ! a group input with a given domain; an output set and read back.
    VAR signaldi sensor;
    VAR signalgi recipe;
    VAR signaldo lamp;
    VAR num twice := 0;
    VAR num first := 0;
    VAR num second := 0;
    VAR bool agree := TRUE;
    VAR num code := 0;
    VAR num scaled := 0;
    VAR num echo := -1;
    VAR bool lit := FALSE;

    PROC main()
        AliasIO "DI_SENSOR", sensor;
        AliasIO "GI_RECIPE", recipe;
        AliasIO "DO_LAMP", lamp;
        WHILE TRUE DO
            twice := sensor + DInput(sensor);
            first := DInput(di_free);
            second := DInput(di_free);
            agree := first = second;
            IF sensor = 1 AND DInput(sensor) = 0 THEN
                twice := -1;
            ENDIF
            code := GInput(recipe);
            scaled := GInput(recipe) * 2 + code;
            IF code > 2 THEN
                SetDO lamp, 1;
            ELSE
                SetDO lamp, 0;
            ENDIF
            echo := DOutput(lamp);
            lit := lamp = 1;
        ENDWHILE
    ENDPROC
ENDMODULE
