MODULE RuntimeDivCopied
    ! The input is read once into count; the division uses the copy.
    VAR num ratio := 0;
    VAR num count := 0;

    PROC main()
        WHILE TRUE DO
            count := DInput(di_count);
            IF count <> 0 THEN
                ratio := 10 / count;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
