MODULE DomainTestCases
    ! A recipe number read from a group input (no --input-domain, no EIO.cfg).
    ! It is only the subject of TEST with number CASE values, so the checker
    ! derives the default domain {0, 1, 2, 3, 4} (each value, its neighbours, 0).
    VAR signalgi gi_recipe;
    VAR num recipe := 0;

    PROC main()
        AliasIO "GI_RECIPE", gi_recipe;
        WHILE TRUE DO
            TEST GInput(gi_recipe)
            CASE 1:
                recipe := 1;
            CASE 2, 3:
                recipe := 2;
            DEFAULT:
                recipe := 9;
            ENDTEST
        ENDWHILE
    ENDPROC
ENDMODULE
