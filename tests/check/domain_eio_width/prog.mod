MODULE DomainEioWidth
    ! giRecipe is a 4-bit group input of EIO.cfg (-DeviceMap "16-19"): its
    ! default domain is every value 0..15, even though its value is assigned.
    VAR num recipe := 0;

    PROC main()
        WHILE TRUE DO
            recipe := GInput(giRecipe);
        ENDWHILE
    ENDPROC
ENDMODULE
